#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Every result names the code that made it (issue 25, item 3): `roughroll --version` prints
# "roughroll X.Y.Z" (the VERSION file) and exits 0; every JSON output has "version": "X.Y.Z";
# every CSV the program writes starts with the line "# roughroll X.Y.Z", and the curve CSV's
# `#` lines name the scene, the method and n and explain every column.
# Usage: cli_version.sh path/to/roughroll
set -u
# bin, src, data, dir, fail, hang_guard, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"

version=$(head -n 1 "$src/VERSION")
[[ $version =~ ^[0-9]+\.[0-9]+\.[0-9]+$ ]] || fail "VERSION holds '$version', not X.Y.Z"

# --- --version
"$bin" --version >"$dir/out" 2>"$dir/err"
status=$?
if [ "$status" -eq 0 ] && [ "$(cat "$dir/out")" = "roughroll $version" ] && [ ! -s "$dir/err" ]; then
    echo "ok   --version: $(cat "$dir/out")"
else
    fail "--version: status $status, stdout '$(cat "$dir/out")', stderr '$(cat "$dir/err")'"
fi

# --- JSON: "version" at the top level of each object.
json_version() {  # json_version NAME FILE
    local got
    got=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1])).get("version", "(none)"))' "$2" 2>&1)
    [ "$got" = "$version" ] && echo "ok   $1: \"version\": \"$got\"" || fail "$1: version '$got', expected '$version'"
}
timeout "$hang_guard" "$bin" point "$data/fig2a-T1.toml" --n 32 --json >"$dir/point.json" 2>"$dir/err" ||
    fail "point --json: $(cat "$dir/err")"
json_version "point --json" "$dir/point.json"
timeout "$hang_guard" "$bin" roughness "$data/roughness/flat-linear.toml" --json >"$dir/roughness.json" 2>"$dir/err" ||
    fail "roughness --json: $(cat "$dir/err")"
json_version "roughness --json" "$dir/roughness.json"

# --- CSV: the first line is "# roughroll X.Y.Z".
first_line() {  # first_line NAME FILE
    local got
    got=$(head -n 1 "$2" 2>/dev/null)
    [ "$got" = "# roughroll $version" ] && echo "ok   $1: $got" || fail "$1: first line '$got', expected '# roughroll $version'"
}
timeout "$hang_guard" "$bin" curve "$data/fig2a-T1.toml" --points 3 >"$dir/curve.csv" 2>"$dir/err" || fail "curve: $(cat "$dir/err")"
first_line "curve (stdout)" "$dir/curve.csv"
timeout "$hang_guard" "$bin" curve "$data/steel-rollers.toml" --points 2 --sweep --csv "$dir/physical.csv" 2>"$dir/err" ||
    fail "curve --csv: $(cat "$dir/err")"
first_line "curve --csv (physical, swept)" "$dir/physical.csv"
timeout "$hang_guard" "$bin" traction "$data/fig2a-T1.toml" --points 5 --out "$dir" --name t --no-plot 2>"$dir/err" ||
    fail "traction: $(cat "$dir/err")"
first_line traction "$dir/traction-t.csv"
timeout "$hang_guard" "$bin" figure 2a --points 2 --out "$dir" --no-plot 2>"$dir/err" || fail "figure: $(cat "$dir/err")"
first_line figure "$dir/fig2a.csv"
timeout "$hang_guard" "$bin" convergence "$data/fig2a-T1.toml" --max-seconds 0.001 --out "$dir" --no-plot >/dev/null 2>"$dir/err" ||
    fail "convergence: $(cat "$dir/err")"
first_line convergence "$dir/convergence-fig2a-T1.csv"

# --- The curve CSV's header lines: the scene, its label, the method and n, then the column
# line, each of whose columns the `#` lines explain.
curve_header() {  # curve_header NAME FILE SCENE METHOD N
    local name=$1 file=$2 comments columns column missing=""
    comments=$(grep '^#' "$file")
    columns=$(grep -v '^#' "$file" | head -n 1)
    awk '/^#/ && data { bad = 1 } !/^#/ { data = 1 } END { exit bad }' "$file" ||
        fail "$name: a '#' line after the column line"
    grep -qxF "# roughroll curve $3: $(grep -m 1 '^label' "$3" | sed 's/^label = "//; s/"$//')" <<<"$comments" ||
        fail "$name: no '# roughroll curve $3: LABEL' line"
    grep -qF "method = $4, n = $5" <<<"$comments" || fail "$name: no 'method = $4, n = $5' in the '#' lines"
    for column in ${columns//,/ }; do
        grep -qE "(^|[ ,;])$column( |,|:|$)" <<<"$comments" || missing="$missing $column"
    done
    [ -z "$missing" ] && echo "ok   $name: scene, label, method, n and every column explained" ||
        fail "$name: columns without an explanation:$missing"
}
curve_header "curve header" "$dir/curve.csv" "$data/fig2a-T1.toml" product 96
curve_header "curve header (physical)" "$dir/physical.csv" "$data/steel-rollers.toml" extrapolated 128
grep -q '^# SI: ' "$dir/physical.csv" || fail "curve header (physical): no '# SI:' line"
grep -q '^# SI: ' "$dir/curve.csv" && fail "curve header: a '# SI:' line for a dimensionless scene"

finish

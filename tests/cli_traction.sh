#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `roughroll traction --no-plot` on scenes of data/: the CSV has its header and K rows,
# and the tractions satisfy the paper's conditions on the grid:
#   p >= 0;  |p1| <= f p (3.3, everywhere, to 1e-12);  p1 = f p on the slip zone (3.5, to 1e-12);
#   the zone is stick, then slip, switching once, at c0 (the c0 of the header comment).
# Each check is also run on a CSV corrupted to break it, and must fail there.
# Usage: cli_traction.sh path/to/roughroll
set -u
# bin, data, dir, fail, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"

columns='r,p,p1,f_p,minus_f_p,zone,slip_velocity'

# check_csv FILE K: prints one line per violated check, exits 1 if any.
check_csv() {
    awk -F, -v K="$2" -v columns="$columns" '
    function bad(what) { if (!(what in seen)) { print "  " what; seen[what] = 1 }; failed = 1 }
    function abs(x) { return x < 0 ? -x : x }
    /^# Q = / {
        n = split(substr($0, 3), parts, ", ")
        for (i = 1; i <= n; ++i) { split(parts[i], kv, " = "); meta[kv[1]] = kv[2] }
        next
    }
    /^#/ { next }
    !header_seen {
        header_seen = 1
        if (index($0, columns) != 1) bad("header is \"" $0 "\", expected it to start with " columns)
        next
    }
    {
        ++rows
        r = $1; p = $2; p1 = $3; zone = $6
        if (!("f" in meta) || !("c0" in meta)) { bad("no \"# Q = ..., f = ..., c0 = ...\" comment line"); next }
        f = meta["f"] + 0; c0 = meta["c0"] + 0
        if (p < 0) bad("p < 0 at r = " r " (p = " p ")")
        if (abs(p1) > f * p + 1e-12) bad("|p1| > f p at r = " r " (p1 = " p1 ", f p = " f * p ")")
        if (zone == "slip" && abs(p1 - f * p) > 1e-12) bad("p1 != f p on the slip zone at r = " r)
        if (zone != "stick" && zone != "slip") bad("zone \"" zone "\" at r = " r)
        if (rows == 1 && zone != "stick") bad("the first grid point (r = " r ") is not in the stick zone")
        if (rows > 1 && zone != last_zone) {
            ++switches
            if (!(last_zone == "stick" && zone == "slip" && last_r < c0 && c0 <= r))
                bad("zone switches from " last_zone " to " zone " between r = " last_r " and " r ", c0 = " c0)
        }
        last_zone = zone; last_r = r
    }
    END {
        if (!header_seen) bad("no header")
        if (rows != K) bad(rows + 0 " rows, expected " K)
        if (c0 > -1 && c0 < 1 && switches != 1) bad((switches + 0) " zone switches, expected 1")
        exit failed
    }' "$1"
}

# A valid CSV from each scene (the default K = 401, and another K).
run() {  # run NAME K SCENE [ARGS...]
    local name=$1 k=$2 scene=$3
    shift 3
    local args=(traction "$data/$scene" --no-plot --out "$dir" --name "$name")
    [ "$k" != 401 ] && args+=(--points "$k")
    if ! "$bin" "${args[@]}" "$@" >"$dir/out" 2>"$dir/err"; then
        fail "$name: roughroll exited $?: $(cat "$dir/err")"
        return
    fi
    [ -s "$dir/out" ] && fail "$name: unexpected output on stdout"
    [ -f "$dir/traction-$name.gp" ] || fail "$name: no gnuplot script"
    [ -e "$dir/traction-$name.png" ] && fail "$name: --no-plot wrote a PNG"
    if check_csv "$dir/traction-$name.csv" "$k" >"$dir/msg"; then
        echo "ok   $name: $(grep -c ',stick,\|,slip,' "$dir/traction-$name.csv") rows, $(grep '^# Q = ' "$dir/traction-$name.csv" | cut -d, -f1-3)"
    else
        fail "$name:"; cat "$dir/msg"
    fi
}

run example 401 traction-example.toml
run example-Qf0.9 201 traction-example.toml --Q 0.27
run unequal 301 unequal-kernels.toml
run fig2b-A0 101 fig2b-A0.toml
# The '# zones' line lists the rows' zones, level n's: with Richardson's c0 in the header (method extrapolated) it says
# so, and only there (docs/cli.md, `traction`).
run example-extrapolated 101 traction-example.toml --method extrapolated
zones_note="^# zones (r = x1/a; the rows' own, at n = [0-9]*, where the header's c0 is extrapolated): stick "
grep -q "$zones_note" "$dir/traction-example-extrapolated.csv" ||
    fail "example-extrapolated: the '# zones' line does not say the rows' ends are level n's"
grep -q "^# zones (r = x1/a): stick " "$dir/traction-example.csv" ||
    fail "example: the '# zones' line is not the plain one"

# Each check must be able to fail: corrupt the valid CSV one way at a time.
good="$dir/traction-example.csv"
expect_failure() {  # expect_failure NAME KEYWORD AWK-PROGRAM
    awk -F, -v OFS=, "$3" "$good" >"$dir/bad.csv"
    if check_csv "$dir/bad.csv" 401 >"$dir/msg"; then
        fail "corrupted CSV '$1' passed the checks"
    elif ! grep -qF -- "$2" "$dir/msg"; then
        fail "corrupted CSV '$1' failed for another reason:"; cat "$dir/msg"
    else
        echo "ok   corrupted '$1' is caught: $(head -1 "$dir/msg" | sed 's/^ *//')"
    fi
}
# (Data rows are the lines after the header: r is numeric there.)
expect_failure header "header is" '/^r,/ { sub(/slip_velocity/, "v") } 1'
expect_failure missing-row "rows, expected" '$1 == "0.5" { next } 1'
expect_failure extra-row "rows, expected" '1; $1 == "1" { print }'
expect_failure negative-p "p < 0" '$1 == "0.5" { $2 = -1e-9 } 1'
expect_failure stick-bound "|p1| > f p" '$6 == "stick" && $1 == "-0.5" { $3 = $4 * 1.0001 } 1'
expect_failure slip-equality "p1 != f p" '$6 == "slip" && $1 == "0.5" { $3 = $4 - 1e-9 } 1'
expect_failure zone-twice "zone switches" '$6 == "slip" && $1 == "0.5" { $6 = "stick" } 1'
expect_failure zone-late "zone switches" 'BEGIN { done = 0 } $6 == "slip" && !done { $6 = "stick"; done = 1 } 1'
expect_failure zone-name "zone \"" '$1 == "-0.5" { $6 = "sticky" } 1'
expect_failure no-meta "comment line" '/^# Q = / { next } 1'

finish

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A load given as Q/f or as P1 wherever a load is given (issue 25): the scene key Q_over_f, the
# options --Q-over-f (point, traction, convergence) and --P1 (physical scenes) solve the same
# point as the Q they stand for, bit for bit; one load only (a scene's Q and Q_over_f, --Q with
# --Q-over-f or --P1 are refused with one line); Q/f outside [-1, 1] or not finite, P1 beyond
# f P2, P1 for a dimensionless scene are refused with one line; a scene's Q_over_f follows
# --friction; a load just below gross sliding never prints as Q/f = 1.
# Usage: cli_loads.sh path/to/roughroll
set -u
# bin, data, dir, fail, hang_guard, expect, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"

# run NAME ARGS...: the program's stdout in $dir/NAME (exit 0 expected).
run() {
    local name=$1
    shift
    timeout "$hang_guard" "$bin" "$@" >"$dir/$name" 2>"$dir/err" || fail "$name: status $?: $(cat "$dir/err")"
}

# same_point NAME A B: the JSON points A and B agree in every field but seconds.
same_point() {
    if python3 - "$dir/$2" "$dir/$3" <<'PY'; then echo "ok   $1"; else fail "$1: the points differ"; fi
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for d in (a, b):
    d.pop("seconds")
sys.exit(0 if a == b else 1)
PY
}

# field FILE KEY: a top-level field of a JSON file (SI fields as si.KEY).
field() {
    python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
for k in sys.argv[2].split("."):
    d = d[k]
print(repr(d))' "$dir/$1" "$2"
}

# --- Dimensionless: Q/f = 0.5 at f = 0.3 is Q = 0.15 exactly.
run q.json point "$data/fig2a-T1.toml" --n 32 --Q 0.15 --json
run ratio.json point "$data/fig2a-T1.toml" --n 32 --Q-over-f 0.5 --json
same_point "point --Q-over-f 0.5 = --Q 0.15" q.json ratio.json
[ "$(field ratio.json Q)" = "0.15" ] && echo "ok   JSON Q = 0.15" || fail "JSON Q: $(field ratio.json Q)"
sed 's/^Q = 0.15/Q_over_f = 0.5/' "$data/fig2a-T1.toml" >"$dir/ratio.toml"
run key.json point "$dir/ratio.toml" --n 32 --json
same_point "scene key Q_over_f = 0.5 = Q = 0.15" q.json key.json
run key-neg.json point "$dir/ratio.toml" --n 32 --Q-over-f -0.5 --json
run q-neg.json point "$data/fig2a-T1.toml" --n 32 --Q -0.15 --json
same_point "--Q-over-f over the scene's Q_over_f" q-neg.json key-neg.json

# The scene's ratio follows --friction: Q_over_f = 0.5 at f = 0.2 is Q = 0.1.
run f02.json point "$dir/ratio.toml" --n 32 --friction 0.2 --json
run f02q.json point "$data/fig2a-T1.toml" --n 32 --friction 0.2 --Q 0.1 --json
same_point "Q_over_f with --friction 0.2 = --Q 0.1" f02q.json f02.json

# traction and convergence take it too (the traction CSV's header names the load).
run traction.out traction "$data/fig2a-T1.toml" --n 32 --Q-over-f 0.5 --points 5 --out "$dir" --name r --no-plot
grep -q '^# Q = 0.15, f = 0.3,' "$dir/traction-r.csv" && echo "ok   traction --Q-over-f: Q = 0.15" ||
    fail "traction --Q-over-f: $(grep '^# Q' "$dir/traction-r.csv")"
run traction-q.out traction "$data/fig2a-T1.toml" --n 32 --Q 0.15 --points 5 --out "$dir" --name q --no-plot
cmp -s <(grep -v '^#' "$dir/traction-r.csv") <(grep -v '^#' "$dir/traction-q.csv") &&
    echo "ok   traction --Q-over-f 0.5 rows = --Q 0.15 rows" || fail "traction: the rows differ"
run convergence.out convergence "$data/fig2a-T1.toml" --Q-over-f 0.5 --max-seconds 0.001 --out "$dir" --no-plot
grep -q '^# roughroll convergence .*, Q = 0.15;' "$dir/convergence-fig2a-T1.csv" && echo "ok   convergence --Q-over-f" ||
    fail "convergence --Q-over-f: $(grep '^# roughroll convergence' "$dir/convergence-fig2a-T1.csv")"

# --- Near gross sliding: Q/f = 1 - 1e-9 prints as such, never as 1.
run near.txt point "$data/fig2a-T1.toml" --n 32 --Q-over-f 0.999999999
grep -qE '^  Q = P1/P2 .*\(Q/f = 0\.99999999[89][0-9]*, f = 0\.3\)' "$dir/near.txt" &&
    echo "ok   near gross sliding: $(grep 'Q = P1/P2' "$dir/near.txt")" || fail "near gross sliding: $(grep 'Q = P1/P2' "$dir/near.txt")"
run near.json point "$data/fig2a-T1.toml" --n 32 --Q-over-f 0.999999999 --json
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["Q"] < d["f"] and abs(d["Q"] / d["f"] - 0.999999999) < 1e-15 else 1)' \
    "$dir/near.json" && echo "ok   near gross sliding: JSON Q < f" || fail "near gross sliding: JSON Q = $(field near.json Q)"
run near-t.out traction "$data/fig2a-T1.toml" --n 32 --Q-over-f 0.999999999 --points 5 --out "$dir" --name near --no-plot
grep -q '(Q/f = 0.999999999)' "$dir/traction-near.gp" && echo "ok   traction plot title: Q/f = 0.999999999" ||
    fail "traction plot title: $(grep -o '(Q/f = [^)]*)' "$dir/traction-near.gp" | head -n 1)"
# The largest double below 1 still solves below gross sliding.
run below.json point "$data/fig2a-T1.toml" --n 32 --Q-over-f 0.99999999999999989 --json
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["Q"] < d["f"] and d["Q"] / d["f"] < 1 else 1)' \
    "$dir/below.json" && echo "ok   Q/f = 1 - 2^-53: Q < f" || fail "Q/f = 1 - 2^-53: Q = $(field below.json Q)"

# --- Physical scenes: --P1 = the scene's P1 (1.5e4 N/m), and --P1 over --Q's load.
run p1-scene.json point "$data/steel-rollers.toml" --n 32 --json
run p1.json point "$data/steel-rollers.toml" --n 32 --P1 15000 --json
same_point "point --P1 15000 = the scene's P1 = 1.5e4" p1-scene.json p1.json
run p1-q.json point "$data/steel-rollers.toml" --n 32 --Q 0.1 --json
run p1-10k.json point "$data/steel-rollers.toml" --n 32 --P1 1e4 --json
same_point "point --P1 1e4 = --Q 0.1 (P2 = 1e5)" p1-q.json p1-10k.json
[ "$(field p1-10k.json si.P1_N_per_m)" = "10000.0" ] && echo "ok   --P1 1e4: si.P1_N_per_m = 10000" ||
    fail "--P1 1e4: si.P1_N_per_m = $(field p1-10k.json si.P1_N_per_m)"
run p1-t.out traction "$data/steel-rollers.toml" --n 32 --P1 1e4 --points 5 --out "$dir" --name p1 --no-plot
grep -q '^# Q = 0.1, f = 0.3,' "$dir/traction-p1.csv" && echo "ok   traction --P1" || fail "traction --P1: $(grep '^# Q' "$dir/traction-p1.csv")"
sed 's/^P1 = 1.5e4 .*/Q_over_f = 0.5/' "$data/steel-rollers.toml" >"$dir/steel-ratio.toml"
run steel-ratio.json point "$dir/steel-ratio.toml" --n 32 --json
same_point "physical scene key Q_over_f = 0.5 = P1 = 1.5e4" p1-scene.json steel-ratio.json

# --- Refused with one line.
printf 'Q = 0.15\n' | cat - "$dir/ratio.toml" >"$dir/both.toml"
expect scene-Q-and-Q_over_f "not both" -- point "$dir/both.toml"
sed 's/^P1 = 1.5e4 .*/P1 = 1.5e4\nQ_over_f = 0.5/' "$data/steel-rollers.toml" >"$dir/steel-both.toml"
expect scene-P1-and-Q_over_f "not both" -- point "$dir/steel-both.toml"
for bad in 1.5 -1.0000001 nan inf -inf; do
    sed "s/^Q = 0.15/Q_over_f = $bad/" "$data/fig2a-T1.toml" >"$dir/bad.toml"
    expect "scene-Q_over_f=$bad" "'Q_over_f' must" -- point "$dir/bad.toml"
    expect "--Q-over-f $bad" "Q_over_f must" -- point "$data/fig2a-T1.toml" --Q-over-f="$bad"
done
printf 'friction = 0.3\nQ_over_f = "half"\n' >"$dir/bad-type.toml"
expect scene-Q_over_f-string "Q_over_f" -- point "$dir/bad-type.toml"
expect Q-over-f-text "--Q-over-f" -- point "$data/fig2a-T1.toml" --Q-over-f half
expect Q-and-Q-over-f "excludes" -- point "$data/fig2a-T1.toml" --Q 0.1 --Q-over-f 0.5
expect Q-and-P1 "excludes" -- point "$data/steel-rollers.toml" --Q 0.1 --P1 1e4
expect Q-over-f-and-P1 "excludes" -- traction "$data/steel-rollers.toml" --Q-over-f 0.1 --P1 1e4 --out "$dir" --no-plot
expect P1-dimensionless "physical scene" -- point "$data/fig2a-T1.toml" --P1 1e4
expect P1-dimensionless-traction "physical scene" -- traction "$data/fig2a-T1.toml" --P1 1e4 --out "$dir" --no-plot
expect P1-slides "slide" -- point "$data/steel-rollers.toml" --P1 30001
expect P1-nan "P1 must be finite" -- point "$data/steel-rollers.toml" --P1 nan
sed 's/^P1 = 1.5e4 .*/Q = 0.15\ncontact_width = "hertz"/' "$data/steel-rollers.toml" >"$dir/hertz.toml"
expect P1-hertz-width "given-load" -- point "$dir/hertz.toml" --P1 1e4
expect convergence-Q-over-f-above-1 "Q_over_f must" -- convergence "$data/fig2a-T1.toml" --Q-over-f 2 --out "$dir" --no-plot

finish

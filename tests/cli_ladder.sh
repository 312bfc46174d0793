#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The ladder that chooses n (problems/level_ladder.hpp, docs/cli.md --tolerance) at the command
# line: the one-parameter case near gross sliding (eps1 = 0.1, eps2 = 0.3, Q/f = 0.9999), whose
# checks fail at the default n = 128, is answered without --n at n = 1000 (its stick start's estimate,
# docs/formulation.md 7(e) "The start's estimate"; n = 256 at --tolerance 1e-3) and says so in the JSON
# and the text; --n 128 is today's flagged point; a tolerance no n reaches is refused (exit 2, one
# line naming the best estimate); a curve reports each row's n in its column n (the given n with --n).
# Usage: cli_ladder.sh path/to/roughroll
set -u
# bin, dir, fail, hang_guard, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"

cat >"$dir/near.toml" <<'EOF'
friction = 0.3
Q = 0.29997
[cylinder1.tangential]
T = 0.05
A = 1
[cylinder1.normal]
T = 0.15
A = 1
[solver]
method = "one-parameter"
EOF

run() { timeout "$hang_guard" "$bin" "$@"; }
field() { python3 -c 'import json, sys; print(json.dumps(json.load(sys.stdin)[sys.argv[1]]))' "$1"; }

# Rung 512's stick start +- 4.5e-6 is above 1e-4 (1 + s) = 2.1e-6 (before session 26 rung 256 answered, its start
# printed without an estimate, 5.6e-6 from n = 1000's).
json=$(run point "$dir/near.toml" --json) || fail "point without n: exit $?"
[ "$(field n <<<"$json")" = 1000 ] || fail "point without n: not at n = 1000: $(field n <<<"$json")"
[ "$(field checks_hold <<<"$json")" = true ] || fail "point without n: checks fail"
[ "$(field error_estimate <<<"$json")" != null ] || fail "point without n: no estimate"
python3 -c 'import json, sys; j = json.load(sys.stdin); e = j["error_estimate"]["stick_start"]
sys.exit(not 0 < e <= 1e-4 * (1 + j["stick_start"]))' <<<"$json" || fail "point without n: stick start's estimate"
text=$(run point "$dir/near.toml" --tolerance 1e-3) || fail "point text: exit $?"
grep -q '^  method, n           one-parameter, 256$' <<<"$text" || fail "point text: n not 256: $text"
grep -q '^  error estimate      P_H/P2 .*, c0 .*, stick start .*, xi ' <<<"$text" || fail "point text: no start's estimate: $text"

# A kernel too steep for n/2 = 64 ("increase n" at n = 128, cli_bad_input.sh): the ladder increases it.
printf 'friction = 0.3\nQ = 0.15\n[cylinder1.normal]\nT = 1\nA = 300\n' >"$dir/steep.toml"
json=$(run point "$dir/steep.toml" --json) || fail "steep kernel without n: exit $?"
[ "$(field n <<<"$json")" = 256 ] || fail "steep kernel without n: not at n = 256"

json=$(run point "$dir/near.toml" --json --n 128) || fail "point --n 128: exit $?"
[ "$(field n <<<"$json")" = 128 ] || fail "--n 128: not at 128"
[ "$(field checks_hold <<<"$json")" = false ] || fail "--n 128: not today's flagged point"
[ "$(field error_estimate <<<"$json")" = null ] || fail "--n 128: an estimate on a flagged point"

run point "$dir/near.toml" --Q 0.15 --tolerance 1e-9 >"$dir/out" 2>"$dir/err"  # order 2: out of reach at 1000
status=$?
[ "$status" -eq 2 ] || fail "--tolerance 1e-9: exit $status, expected 2"
[ "$(wc -l <"$dir/err")" -eq 1 ] || fail "--tolerance 1e-9: not one stderr line: $(cat "$dir/err")"
grep -q 'no n up to 1000 meets the tolerance 1e-09 (relative): the best estimate reached is .* at n = ' "$dir/err" ||
    fail "--tolerance 1e-9: $(cat "$dir/err")"
[ -s "$dir/out" ] && fail "--tolerance 1e-9: wrote stdout"

# A load below the load equation's precision is beyond every n: refused at the first rung with its own advice,
# no ladder advice after it (issue 24: "give n to see that point" was added, which no n answers). A rung's
# refusal that names its change (a kernel too steep for 'extrapolated' at every n: use method 'product') keeps
# it alone; validation/test_ladder_refusals.cpp has the ladder's advice after a refusal naming none.
run point "$dir/near.toml" --Q 1e-12 >"$dir/out" 2>"$dir/err"
status=$?
[ "$status" -eq 2 ] || fail "--Q 1e-12: exit $status, expected 2"
grep -q 'is below 1e-10, the relative precision of the load equation .* at any n; give |Q|/f >= 1e-10, or Q = 0 (solved exactly)$' "$dir/err" ||
    fail "--Q 1e-12: not its own advice alone: $(cat "$dir/err")"
grep -q 'no n up to' "$dir/err" && fail "--Q 1e-12: the ladder climbed: $(cat "$dir/err")"
printf 'friction = 0.3\nQ = 0.15\n[cylinder1.normal]\nT = 1\nA = 20000\n' >"$dir/steeper.toml"
run point "$dir/steeper.toml" >"$dir/out" 2>"$dir/err"
status=$?
[ "$status" -eq 2 ] || fail "A = 20000: exit $status, expected 2"
grep -q "; use method 'product' (no n up to 1000 resolves them at n/2))\$" "$dir/err" ||
    fail "A = 20000: not its own advice alone: $(cat "$dir/err")"

run curve "$dir/near.toml" --points 3 --csv "$dir/c.csv" 2>"$dir/err"
status=$?
[ "$status" -eq 0 ] || [ "$status" -eq 3 ] || fail "curve: exit $status: $(cat "$dir/err")"
grep -q '^# f = 0.3, method = one-parameter, n = 128 (the method.s default; a row climbs to larger n, column n, until its estimates are below the relative tolerance 1e-04), zones' "$dir/c.csv" ||
    fail "curve header: $(head -3 "$dir/c.csv")"
grep -q ',n,status$' "$dir/c.csv" || fail "curve: no column n"
grep -q ',zones,stick_start,stick_start_error_estimate,zone_path,' "$dir/c.csv" || fail "curve: no start's estimate column"
# P_H/P2 of this scene is estimated at 1.8e-4 relative at n = 128 (every row's), 4.5e-5 at 256; the row at gross
# sliding (Q/f = 1, the stick zone a point at r = -0.952) climbs to 512 for its stick start (+- 4.5e-6 within
# 1e-4 (1 + s) = 4.8e-6; at 256 it was above, printed unestimated before session 26), every row's start's estimate
# within the tolerance.
[ "$(grep -v '^#' "$dir/c.csv" | tail -n +2 | cut -d, -f16 | tr '\n' ' ')" = "256 256 512 " ] ||
    fail "curve: rows not at n = 256, 256, 512: $(cat "$dir/c.csv")"
grep -v '^#' "$dir/c.csv" | tail -n +2 | awk -F, '{ if ($17 != "ok" || $14 == "" || $14 > 1e-4 * (1 + $13)) exit 1 }' ||
    fail "curve: a start's estimate above the tolerance: $(cat "$dir/c.csv")"
run curve "$dir/near.toml" --points 3 --n 128 --csv "$dir/c128.csv" 2>"$dir/err" || fail "curve --n 128: exit $?"
[ "$(grep -v '^#' "$dir/c128.csv" | tail -n +2 | grep -vc ',128,ok$')" = 0 ] || fail "curve --n 128: a row not at 128"

finish

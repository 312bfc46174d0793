#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `roughroll curve` with refused points (README.md "Creep curves", docs/robustness.md): a point
# without an honest error estimate is a row with status `refused` and its computed fields empty,
# one stderr line names it, the rest of the curve is computed, and the exit status is 3.
# Which rows must be refused is decided independently, by `roughroll point --Q` on each load
# alone (exit 2, "no honest error estimate"); an answered row must be that point's xi.
# The scene: a very stiff normal layer (T = 1e6, A = 1 on cylinder 2) at n = 16, product.
# Usage: cli_curve.sh path/to/roughroll
set -u
# bin, data, dir, fail, hang_guard, stiff_scene, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"

printf '%s\n' "$stiff_scene" >"$dir/stiff.toml"

# data_lines FILE: FILE without the `#` lines the CSV starts with (version, scene, column notes:
# cli_version.sh checks them), the whole CSV kept in FILE.full.
data_lines() { cp "$1" "$1.full" && sed -i '/^#/d' "$1"; }

# column NAME: its index in the header of $dir/out.
column() { head -1 "$dir/out" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }

# --- Given loads: every row against the point solved alone.
timeout "$hang_guard" "$bin" curve "$dir/stiff.toml" --points 7 >"$dir/out" 2>"$dir/err"
status=$?
data_lines "$dir/out"
[ "$status" -eq 3 ] || fail "stiff curve: exit status $status, expected 3 (partial output)"
[ "$(head -1 "$dir/out" | awk -F, '{ print $NF }')" = status ] || fail "stiff curve: the last column is not status"
[ "$(tail -n +2 "$dir/out" | wc -l)" -eq 7 ] || fail "stiff curve: $(tail -n +2 "$dir/out" | wc -l) rows, expected 7"
width=$(head -1 "$dir/out" | awk -F, '{ print NF }')
refused=0 answered=0
while IFS=, read -r Q Qf rest; do
    row="$Q,$Qf,$rest"
    [ "$(echo "$row" | awk -F, '{ print NF }')" -eq "$width" ] || fail "row Q = $Q is not $width fields wide: $row"
    state=${row##*,}
    timeout "$hang_guard" "$bin" point "$dir/stiff.toml" --Q "$Q" --json >"$dir/pout" 2>"$dir/perr"
    pstatus=$?
    if [ "$pstatus" -eq 2 ] && grep -q "no honest error estimate" "$dir/perr"; then
        refused=$((refused + 1))
        [ "$state" = refused ] || fail "Q = $Q: refused alone, '$state' on the curve"
        # c0, xi, xi_over_f, checks_hold .. stick_start: empty (never a plausible number).
        for name in c0 xi xi_over_f checks_hold c0_error_estimate xi_error_estimate zones stick_start stick_start_error_estimate zone_path; do
            k=$(column "$name")
            [ -z "$(echo "$row" | cut -d, -f"$k")" ] || fail "Q = $Q refused but $name = $(echo "$row" | cut -d, -f"$k")"
        done
        line="roughroll: refused: curve point at Q = $Q (Q/f = $Qf): $(sed 's/^roughroll: error: //' "$dir/perr")"
        grep -qxF -- "$line" "$dir/err" || fail "Q = $Q: no stderr line '$line'"
    elif [ "$pstatus" -eq 0 ]; then
        answered=$((answered + 1))
        [ "$state" = ok ] || fail "Q = $Q: answered alone, '$state' on the curve"
        xi=$(echo "$row" | cut -d, -f"$(column xi)")
        alone=$(grep -m1 '^  "xi":' "$dir/pout" | sed 's/.*: *//; s/,$//')
        awk -v a="$xi" -v b="$alone" 'BEGIN { exit !(a + 0 == b + 0 && a != "") }' ||
            fail "Q = $Q: xi = '$xi' on the curve, $alone alone"
    else
        fail "Q = $Q alone: exit status $pstatus: $(cat "$dir/perr")"
    fi
done < <(tail -n +2 "$dir/out")
[ "$refused" -ge 1 ] && [ "$answered" -ge 2 ] || fail "the scene must give refused and answered rows ($refused, $answered)"
[ "$(wc -l <"$dir/err")" -eq "$refused" ] || fail "$(wc -l <"$dir/err") stderr lines for $refused refused points"
echo "given loads: $answered answered, $refused refused, exit $status"

# --- The same curve into a file: the same CSV, the same status.
timeout "$hang_guard" "$bin" curve "$dir/stiff.toml" --points 7 --csv "$dir/curve.csv" >"$dir/out2" 2>"$dir/err2"
status=$?
[ "$status" -eq 3 ] || fail "--csv: exit status $status, expected 3"
cmp -s "$dir/out.full" "$dir/curve.csv" || fail "--csv: the file differs from stdout's CSV"
cmp -s "$dir/err" "$dir/err2" || fail "--csv: other stderr lines"
[ -s "$dir/out2" ] && fail "--csv: something on stdout"

# --- Swept in c0: a refused row keeps its c0, its load (not found) is empty.
timeout "$hang_guard" "$bin" curve "$dir/stiff.toml" --points 5 --sweep >"$dir/out" 2>"$dir/err"
status=$?
data_lines "$dir/out"
[ "$status" -eq 3 ] || fail "swept: exit status $status, expected 3"
awk -F, 'NR > 1 && $NF == "refused" { if ($1 != "" || $3 == "" || $4 != "") bad = 1; n++ }
         END { exit !(n >= 1 && !bad) }' "$dir/out" || fail "swept: refused rows must have c0 only: $(cat "$dir/out")"
grep -q '^roughroll: refused: curve point at c0 = ' "$dir/err" || fail "swept: no stderr line naming c0"
[ "$(wc -l <"$dir/err")" -eq "$(grep -c ',refused$' "$dir/out")" ] || fail "swept: one stderr line per refused row"
# A load Q(c0) outside [0, f] (here -28.8 at c0 = 0.5 with method product) is no physical point:
# refused, never an answered row; Carter's columns (xi_carter, c0_carter) are numbers in every row.
grep -qi 'nan' "$dir/out" && fail "swept: nan in the CSV: $(grep -i nan "$dir/out")"
awk -F, -v f=0.3 'NR > 1 && $NF == "ok" && ($1 < 0 || $1 > f) { bad = 1 } END { exit bad }' "$dir/out" ||
    fail "swept: an answered row with Q outside [0, f]: $(cat "$dir/out")"
awk -F, 'NR > 1 && ($6 == "" || $7 == "") { bad = 1 } END { exit bad }' "$dir/out" ||
    fail "swept: a row without Carter's columns: $(cat "$dir/out")"
grep -q '^roughroll: refused: curve point at c0 = 0.5: Q(c0) = [-0-9.e+]* lies outside \[0, f\] = \[0, 0.3\]' "$dir/err" ||
    fail "swept: c0 = 0.5 (Q = -28.8) not refused as outside [0, f]: $(cat "$dir/err")"

# --- A curve without a refusal: exit 0, nothing on stderr, every status ok.
timeout "$hang_guard" "$bin" curve "$data/fig2a-T1.toml" --points 5 >"$dir/out" 2>"$dir/err"
status=$?
data_lines "$dir/out"
[ "$status" -eq 0 ] || fail "clean curve: exit status $status"
[ -s "$dir/err" ] && fail "clean curve: stderr $(cat "$dir/err")"
[ "$(tail -n +2 "$dir/out" | grep -c ',ok$')" -eq 5 ] || fail "clean curve: not every row ok"

# --- Each row's zone_path, as the point's (docs/formulation.md 7(i)): aluminium on steel at f = 5, Q/f = -1, 0, 1.
# Free rolling is answered with its edge layers neglected (8(n)): the row says no-slip, as the point does;
# the paper's smooth rollers say single.
timeout "$hang_guard" "$bin" curve "$data/aluminium-on-steel.toml" --friction 5 --points 3 >"$dir/out" 2>"$dir/err" ||
    fail "zone_path: the curve failed: $(cat "$dir/err")"
data_lines "$dir/out"
k=$(column zone_path)
[ -n "$k" ] || fail "zone_path: no such column: $(head -1 "$dir/out")"
[ "$(tail -n +2 "$dir/out" | cut -d, -f"$k" | tr '\n' ' ')" = "general no-slip general " ] ||
    fail "zone_path: rows $(tail -n +2 "$dir/out" | cut -d, -f"$k" | tr '\n' ' '), expected general no-slip general"
timeout "$hang_guard" "$bin" point "$data/aluminium-on-steel.toml" --friction 5 --Q 0 --json >"$dir/pout" 2>"$dir/perr" ||
    fail "zone_path: the point failed: $(cat "$dir/perr")"
grep -q '"zone_path": "no-slip"' "$dir/pout" || fail "zone_path: the point at Q = 0 is not no-slip"
timeout "$hang_guard" "$bin" curve "$data/fig2a-T1.toml" --points 3 >"$dir/out" 2>"$dir/err" || fail "zone_path: Fig. 2a failed"
data_lines "$dir/out"
[ "$(tail -n +2 "$dir/out" | cut -d, -f"$(column zone_path)" | sort -u)" = single ] || fail "zone_path: Fig. 2a rows not single"

# --- Dissimilar rollers swept (issue 24, 7): the loads of the curve without --sweep, each row continued from the
# previous row's zones; every row the same point, its xi within the row's estimate of the other's.
timeout "$hang_guard" "$bin" curve "$data/aluminium-on-steel.toml" --points 6 --sweep >"$dir/out" 2>"$dir/err" ||
    fail "dissimilar sweep: the curve failed: $(cat "$dir/err")"
grep -q '^# .*swept in the load: Q/f over the curve' "$dir/out" || fail "dissimilar sweep: the header does not say so"
data_lines "$dir/out"
cp "$dir/out" "$dir/swept"
timeout "$hang_guard" "$bin" curve "$data/aluminium-on-steel.toml" --points 6 >"$dir/out" 2>"$dir/err" ||
    fail "dissimilar sweep: the curve at given loads failed: $(cat "$dir/err")"
data_lines "$dir/out"
k=$(column xi) e=$(column xi_error_estimate) z=$(column zones)
paste -d, <(cut -d, -f1,"$k","$e","$z" "$dir/swept") <(cut -d, -f1,"$k","$e","$z" "$dir/out") |
    awk -F, 'NR > 1 { d = $2 - $6; if (d < 0) d = -d; if ($1 != $5 || $4 != $8 || !(d <= $3) || $3 == "") bad = 1; n++ }
             END { exit !(n == 6 && !bad) }' || fail "dissimilar sweep: rows differ from the curve at given loads"

# --- Bad input still aborts at once: exit 2, one line, nothing written.
timeout "$hang_guard" "$bin" curve "$dir/stiff.toml" --points 1 --csv "$dir/bad.csv" >"$dir/out" 2>"$dir/err"
status=$?
[ "$status" -eq 2 ] || fail "bad input: exit status $status, expected 2"
[ "$(wc -l <"$dir/err")" -eq 1 ] || fail "bad input: $(wc -l <"$dir/err") stderr lines"
[ -e "$dir/bad.csv" ] && fail "bad input: the CSV was written"

# --- --friction F is the scene with friction = F: the same curve, byte for byte (fig2a-T1.toml
# with its friction key replaced; the loads Q/f are the curve's own, so Q scales with f).
sed 's/^friction = .*/friction = 0.5/' "$data/fig2a-T1.toml" >"$dir/f05.toml"
grep -qx 'friction = 0.5' "$dir/f05.toml" || fail "--friction: the scene copy has no friction line to replace"
timeout "$hang_guard" "$bin" curve "$dir/f05.toml" --points 5 >"$dir/file.csv" 2>"$dir/err" || fail "--friction: the scene copy's curve failed"
timeout "$hang_guard" "$bin" curve "$data/fig2a-T1.toml" --friction 0.5 --points 5 >"$dir/option.csv" 2>"$dir/err" ||
    fail "--friction: the curve with --friction failed: $(cat "$dir/err")"
# The same but the line naming the scene file.
cmp -s <(grep -v '^# roughroll curve ' "$dir/file.csv") <(grep -v '^# roughroll curve ' "$dir/option.csv") ||
    fail "--friction: the curve differs from the scene with that friction"

finish

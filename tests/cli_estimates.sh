#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The estimates the figure's CSV and the traction header print (session 27 review R12; docs/cli.md):
#   `roughroll figure 2a`: after checks_hold, Q_over_f_i_error_estimate and xi_over_f_i_error_estimate for each
#   curve i, every cell a positive number, each curve's equal to `roughroll curve --sweep` of the same rough layer
#   (data/fig2a-T0.toml, -T0.5, -T1: the figure's curves 1-3) at the same n and c0: its Q_error_estimate and
#   xi_error_estimate divided by f (the figure's rows are those rows);
#   `roughroll traction`: the header line "# error estimate: c0 C, xi X, P_H/P2 L; SI: a A m, P2 P N/m, xi1 Y" holds
#   the numbers `roughroll point --json` prints for the same point (error_estimate c0, xi, hertz_load_ratio;
#   si.error_estimate a_m, P2_N_per_m, xi1).
# Each check is also run on a copy corrupted to break it (a column dropped, a value changed), and must fail there.
# Usage: cli_estimates.sh path/to/roughroll
set -u
# bin, data, dir, fail, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"
command -v python3 >/dev/null || { echo "python3 not found: skipped"; exit 77; }

# check_figure FIG_CSV CURVE1 CURVE2 CURVE3: prints what is wrong, exits 1 if anything.
check_figure() {
    python3 - "$@" <<'EOF'
import csv, sys
def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))
def header(path):
    with open(path) as f:
        return next(line for line in f if not line.startswith("#")).strip().split(",")
bad = []
fig = sys.argv[1]
cols = header(fig)
want = ["checks_hold"] + [f"{q}_over_f_{i}_error_estimate" for i in (1, 2, 3) for q in ("Q", "xi")]
at = cols.index("checks_hold") if "checks_hold" in cols else -1
if cols[at:at + len(want)] != want:
    bad.append(f"figure header {cols}: expected {want} from checks_hold on")
figure = rows(fig)
f = 0.3  # the figure's friction (figure.cpp): the columns are the estimates over f
for i, curve_csv in enumerate(sys.argv[2:], start=1):
    curve = [r for r in rows(curve_csv)]
    if len(curve) != len(figure):
        bad.append(f"curve {i}: {len(curve)} rows against the figure's {len(figure)}")
        continue
    for row, c in zip(figure, curve):
        for q in ("Q", "xi"):
            cell = row.get(f"{q}_over_f_{i}_error_estimate", "")
            try:
                value = float(cell)
            except ValueError:
                bad.append(f"c0 = {row.get('c0')}: curve {i}'s {q} estimate '{cell}' is not a number")
                continue
            expected = float(c[f"{q}_error_estimate"]) / f
            if not value > 0.0 or abs(value - expected) > 1e-14 * expected:
                bad.append(f"c0 = {row.get('c0')}: curve {i}'s {q} estimate {value}, the curve's over f {expected}")
        if abs(float(row[f"Q_over_f_{i}"]) - float(c["Q_over_f"])) > 1e-15:
            bad.append(f"c0 = {row.get('c0')}: curve {i}'s Q/f {row[f'Q_over_f_{i}']} is not the curve's {c['Q_over_f']}")
for line in bad[:8]:
    print("  " + line)
sys.exit(1 if bad else 0)
EOF
}

# check_traction TRACTION_CSV POINT_JSON: the header's estimate line against the point's JSON.
check_traction() {
    python3 - "$@" <<'EOF'
import json, re, sys
with open(sys.argv[1]) as f:
    lines = [l.strip() for l in f if l.startswith("# error estimate")]
j = json.load(open(sys.argv[2]))
e, s = j["error_estimate"], j["si"]["error_estimate"]
want = [("c0", e["c0"]), ("xi", e["xi"]), ("P_H/P2", e["hertz_load_ratio"]),
        ("a", s["a_m"]), ("P2", s["P2_N_per_m"]), ("xi1", s["xi1"])]
if len(lines) != 1:
    print(f"  {len(lines)} error estimate lines in the header")
    sys.exit(1)
bad = []
for name, value in want:
    m = re.search(r"[ ,;]" + re.escape(name) + r" ([-+0-9.e]+)", lines[0])
    if not m:
        bad.append(f"no '{name}' in '{lines[0]}'")
    elif float(m.group(1)) != value:
        bad.append(f"{name} {m.group(1)} in the header, {value!r} in the point's JSON")
for line in bad:
    print("  " + line)
sys.exit(1 if bad else 0)
EOF
}

# The figure at n = 16, four points per curve (about a second), and the three layers' curves swept at the same n.
timeout "$hang_guard" "$bin" figure 2a --points 4 --n 16 --no-plot --quiet --out "$dir/fig" >/dev/null 2>"$dir/err" ||
    fail "figure 2a: $(cat "$dir/err")"
for t in 0 0.5 1; do
    timeout "$hang_guard" "$bin" curve "$data/fig2a-T$t.toml" --sweep --points 4 --n 16 --method extrapolated --quiet \
        --csv "$dir/T$t.csv" 2>"$dir/err" || fail "curve fig2a-T$t: $(cat "$dir/err")"
done
curves=("$dir/T0.csv" "$dir/T0.5.csv" "$dir/T1.csv")
check_figure "$dir/fig/fig2a.csv" "${curves[@]}" || fail "figure 2a's estimate columns"
# Corrupted: an estimate column dropped (the last), and one estimate changed in its last digits.
cut -d, -f1-15 "$dir/fig/fig2a.csv" >"$dir/dropped.csv"
check_figure "$dir/dropped.csv" "${curves[@]}" >/dev/null && fail "a dropped estimate column passes"
awk -F, -v OFS=, '!/^#/ && NR > 3 && !done { $13 = $13 * 1.001; done = 1 } { print }' "$dir/fig/fig2a.csv" \
    >"$dir/changed.csv"
check_figure "$dir/changed.csv" "${curves[@]}" >/dev/null && fail "a changed estimate passes"

# The traction header against the point, a physical scene at a given n (its estimate solved too: docs/cli.md).
scene=$data/steel-rollers-ground.toml
timeout "$hang_guard" "$bin" traction "$scene" --n 48 --method product --points 11 --no-plot --quiet --out "$dir/tr" >/dev/null \
    2>"$dir/err" || fail "traction: $(cat "$dir/err")"
timeout "$hang_guard" "$bin" point "$scene" --n 48 --method product --json --quiet >"$dir/point.json" 2>"$dir/err" ||
    fail "point: $(cat "$dir/err")"
traction_csv=$(ls "$dir"/tr/*.csv)
check_traction "$traction_csv" "$dir/point.json" || fail "the traction header's estimates"
sed 's/^\(# error estimate: c0 [^,]*\), xi [^,]*,/\1,/' "$traction_csv" >"$dir/no-xi.csv"
check_traction "$dir/no-xi.csv" "$dir/point.json" >/dev/null && fail "a header without xi's estimate passes"
sed 's/^\(# error estimate: .*xi1 \)\([0-9]\)/\19\2/' "$traction_csv" >"$dir/xi1.csv"
check_traction "$dir/xi1.csv" "$dir/point.json" >/dev/null && fail "a changed xi1 estimate passes"
finish

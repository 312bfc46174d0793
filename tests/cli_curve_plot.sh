#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `roughroll curve --plot` and the gnuplot scripts of every command (issue 25, items 4 and 5):
#  - curve --plot writes FILE.gp, FILE.svg and FILE.png beside the CSV (a whole PNG, gnuplot's
#    stderr empty); several scenes overlaid (FILE-SCENE.csv each, equal to the scene's curve
#    alone); a physical scene gets the xi1-against-P1 panel; refused rows are drawn as ticks
#    on the load axis (never at a made-up creep) and the exit status stays 3;
#  - every .gp (curve, traction, figure) holds no absolute path: the folder, moved elsewhere,
#    is re-plotted by `cd FOLDER && gnuplot NAME.gp` with no message from gnuplot;
#  - bad input: --plot without --csv, several scenes without --csv: exit 2, one stderr line;
#  - progress: none on a stderr that is not a terminal; --progress gives one line per row and
#    changes no byte of stdout or of the CSV; --quiet with --progress is refused.
# Skipped (77) without gnuplot. Usage: cli_curve_plot.sh path/to/roughroll
set -u
command -v gnuplot >/dev/null || { echo "SKIP: no gnuplot"; exit 77; }
# bin, data, dir, fail, hang_guard, expect, stiff_scene, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"

# whole_png FILE: a PNG signature at the start, the IEND chunk at the end.
whole_png() {
    [ -s "$1" ] && [ "$(head -c 4 "$1" | od -An -c | tr -d ' \n')" = '211PNG' ] &&
        [ "$(tail -c 12 "$1" | od -An -c | tr -d ' \n')" = '\0\0\0\0IEND256B`202' ]
}

# run NAME EXPECTED-STATUS ARGS...: roughroll's status must be EXPECTED-STATUS.
run() {
    local name=$1 expected=$2
    shift 2
    timeout "$hang_guard" "$bin" "$@" >"$dir/out" 2>"$dir/err"
    local status=$?
    if [ "$status" -ne "$expected" ]; then
        fail "$name: exit status $status, expected $expected: $(head -3 "$dir/err")"
        return 1
    fi
    return 0
}

# replot NAME FOLDER SCRIPT IMAGE...: the folder moved to a new place, its images removed, and
# `cd NEW && gnuplot SCRIPT` must write each IMAGE again, whole, with nothing on stderr. The
# script must not name the folder it was written in (nor the test's temporary folder at all).
replot() {
    local name=$1 folder=$2 script=$3
    shift 3
    if grep -qF -- "$dir" "$folder/$script"; then
        fail "$name: $script holds an absolute path: $(grep -F -- "$dir" "$folder/$script" | head -2)"
    fi
    local moved="$dir/moved-$name"
    mv "$folder" "$moved"
    for image in "$@"; do rm -f "$moved/$image"; done
    (cd "$moved" && gnuplot "$script") >"$dir/gp-out" 2>"$dir/gp-err"
    local status=$?
    if [ "$status" -ne 0 ] || [ -s "$dir/gp-err" ]; then
        fail "$name: gnuplot $script in the moved folder: status $status: $(head -3 "$dir/gp-err")"
    fi
    for image in "$@"; do
        case $image in
            *.png) whole_png "$moved/$image" || fail "$name: re-plotted $image is missing or not whole" ;;
            *) [ -s "$moved/$image" ] || fail "$name: re-plotted $image is missing" ;;
        esac
    done
    [ "$failures" -eq "${before:-0}" ] && echo "ok   $name: re-plotted from the moved folder"
}

# --- One dimensionless scene.
mkdir -p "$dir/one"
if run curve-one 0 curve "$data/traction-example.toml" --points 9 --csv "$dir/one/curve.csv" --plot; then
    before=$failures
    [ -s "$dir/err" ] && fail "curve-one: stderr not empty: $(head -3 "$dir/err")"
    [ -s "$dir/out" ] && fail "curve-one: stdout not empty"
    for f in curve.csv curve.gp curve.svg; do [ -s "$dir/one/$f" ] || fail "curve-one: no $f"; done
    whole_png "$dir/one/curve.png" || fail "curve-one: curve.png missing or not whole"
    grep -q "carter(x)" "$dir/one/curve.gp" || fail "curve-one: no Carter curve in curve.gp"
    grep -q "P1_N_per_m" "$dir/one/curve.gp" && fail "curve-one: a physical panel for a dimensionless scene"
    [ "$failures" -eq "$before" ] && echo "ok   curve-one: curve.csv, .gp, .svg, .png"
    # The same CSV as without --plot (stdout).
    run curve-one-stdout 0 curve "$data/traction-example.toml" --points 9 &&
        { cmp -s "$dir/out" "$dir/one/curve.csv" || fail "curve-one: --plot changed the CSV"; }
    before=$failures
    replot curve-one "$dir/one" curve.gp curve.png curve.svg
fi

# --- Two scenes overlaid, one of them physical (its own panel, xi1 against P1).
mkdir -p "$dir/two"
if run curve-two 0 curve "$data/fig2a-T0.5.toml" "$data/steel-rollers.toml" --points 7 --csv "$dir/two/cmp.csv" --plot; then
    before=$failures
    for f in cmp-fig2a-T0.5.csv cmp-steel-rollers.csv cmp.gp cmp.svg; do [ -s "$dir/two/$f" ] || fail "curve-two: no $f"; done
    [ -e "$dir/two/cmp.csv" ] && fail "curve-two: cmp.csv written for two scenes"
    whole_png "$dir/two/cmp.png" || fail "curve-two: cmp.png missing or not whole"
    grep -q "P1_N_per_m" "$dir/two/cmp.gp" || fail "curve-two: no xi1-against-P1 panel for the physical scene"
    [ "$(grep -c "cmp-fig2a-T0.5.csv" "$dir/two/cmp.gp")" -ge 1 ] || fail "curve-two: cmp.gp does not plot the first scene"
    # Each scene's CSV is its curve alone.
    run curve-two-alone 0 curve "$data/steel-rollers.toml" --points 7 &&
        { cmp -s "$dir/out" "$dir/two/cmp-steel-rollers.csv" || fail "curve-two: the overlaid CSV differs from the scene's curve alone"; }
    [ "$failures" -eq "$before" ] && echo "ok   curve-two: two CSVs, one plot with the physical panel"
    before=$failures
    replot curve-two "$dir/two" cmp.gp cmp.png
fi

# --- Refused rows (the stiff layer of cli_curve.sh): exit 3, ticks on the load axis.
printf '%s\n' "$stiff_scene" >"$dir/stiff.toml"
mkdir -p "$dir/refused"
if run curve-refused 3 curve "$dir/stiff.toml" --points 7 --csv "$dir/refused/stiff.csv" --plot; then
    before=$failures
    whole_png "$dir/refused/stiff.png" || fail "curve-refused: stiff.png missing or not whole"
    n=$(grep -c ',refused$' "$dir/refused/stiff.csv")
    [ "$n" -ge 1 ] || fail "curve-refused: no refused row in the CSV (the scene no longer refuses any)"
    [ "$(wc -l <"$dir/err")" -eq "$n" ] || fail "curve-refused: $(wc -l <"$dir/err") stderr lines for $n refused rows"
    grep -q "strcol('status') eq 'refused' ? 0 : NaN" "$dir/refused/stiff.gp" ||
        fail "curve-refused: refused rows not drawn as ticks on the load axis"
    grep -q "$n refused rows (ticks at their load)" "$dir/refused/stiff.gp" || fail "curve-refused: the key does not count the $n refused rows"
    [ "$failures" -eq "$before" ] && echo "ok   curve-refused: $n refused rows as ticks, exit 3"
fi

# --- The other commands' scripts are relative too.
mkdir -p "$dir/trac"
if run traction 0 traction "$data/traction-example.toml" --points 41 --out "$dir/trac" --name t; then
    before=$failures
    replot traction "$dir/trac" traction-t.gp traction-t.png traction-t.svg
fi
if run figure 0 figure 2a --points 5 --n 16 --no-plot --out "$dir/fig"; then
    before=$failures
    replot figure "$dir/fig" fig2a.gp fig2a.png fig2a.svg
fi

# --- The traction plot of aluminium on steel at Q/f = +0.75 (five zones, f = 0.05): every zone
# named (the two at the trailing edge, 3e-4 a wide, too), p1 on a right axis f times p's.
mkdir -p "$dir/five"
if run traction-five 0 traction "$data/aluminium-on-steel.toml" --n 16 --Q 0.0375 --no-plot --out "$dir/five" --name al; then
    before=$failures
    gp="$dir/five/traction-al.gp"
    # One terminal's labels (the script draws the SVG, then the PNG): the zones from the CSV's header.
    zones=$(grep -c '^set label [0-9]* "\(stick zone\|slip zone\|reversed slip\|slip, p_1\)' "$gp")
    [ "$zones" -eq 10 ] || fail "traction-five: $zones zone labels in the script, expected 5 per terminal"
    [ "$(grep -c '^set label [0-9]* "reversed slip' "$gp")" -eq 4 ] || fail "traction-five: the reversed slip zones are not both named"
    grep -q 'a wide)' "$gp" || fail "traction-five: the narrow trailing zones are not marked"
    grep -q 'axes x1y2' "$gp" || fail "traction-five: p1 (f = 0.05) not on the right axis"
    (cd "$dir/five" && gnuplot traction-al.gp) 2>"$dir/gp-err" && [ ! -s "$dir/gp-err" ] ||
        fail "traction-five: gnuplot: $(head -2 "$dir/gp-err")"
    whole_png "$dir/five/traction-al.png" || fail "traction-five: traction-al.png missing or not whole"
    [ "$failures" -eq "$before" ] && echo "ok   traction-five: five zones named, p1 on the right axis"
fi

# --- Bad input: one stderr line, exit 2, nothing written.
expect plot-without-csv "--plot needs --csv" -- curve "$data/traction-example.toml" --points 3 --plot
expect several-without-csv "several scenes need --csv" -- curve "$data/traction-example.toml" "$data/fig2a-T0.toml" --points 3
expect progress-and-quiet "excludes" -- curve "$data/traction-example.toml" --points 3 --progress --quiet
mkdir -p "$dir/same"
cp "$data/fig2a-T0.toml" "$dir/same/fig2a-T0.toml"
expect same-names "two scenes are named" -- curve "$data/fig2a-T0.toml" "$dir/same/fig2a-T0.toml" --points 3 --csv "$dir/same/x.csv"

# --- Progress: one line per row with --progress, none without; stdout unchanged.
if run progress 0 curve "$data/traction-example.toml" --points 5 --progress; then
    cp "$dir/out" "$dir/with-progress"
    rows=$(grep -c '^roughroll: traction-example.toml: row [0-9]*/5, ' "$dir/err")
    [ "$rows" -eq 5 ] || fail "progress: $rows row lines on stderr, expected 5: $(head -3 "$dir/err")"
    grep -qv '^roughroll: ' "$dir/err" && fail "progress: a stderr line without 'roughroll: '"
    run no-progress 0 curve "$data/traction-example.toml" --points 5 &&
        { [ -s "$dir/err" ] && fail "no-progress: stderr not empty on a non-terminal: $(head -2 "$dir/err")"; }
    cmp -s "$dir/out" "$dir/with-progress" || fail "progress: --progress changed stdout"
    [ "$rows" -eq 5 ] && echo "ok   progress: 5 row lines with --progress, none without, stdout the same"
fi
# A traction's progress: a line before its point and one after, nothing in its files.
if run progress-traction 0 traction "$data/traction-example.toml" --points 21 --no-plot --out "$dir/pt" --name a --progress; then
    [ "$(grep -c '^roughroll: traction a: ' "$dir/err")" -eq 2 ] || fail "progress-traction: $(cat "$dir/err")"
    run no-progress-traction 0 traction "$data/traction-example.toml" --points 21 --no-plot --out "$dir/pt" --name b &&
        { [ -s "$dir/err" ] && fail "no-progress-traction: stderr not empty"; }
    cmp -s <(tail -n +2 "$dir/pt/traction-a.csv") <(tail -n +2 "$dir/pt/traction-b.csv") ||
        fail "progress-traction: --progress changed the CSV"
fi
# The physical scene's CSV with --progress (its width once, then the rows) is the same too.
if run progress-physical 0 curve "$data/steel-rollers.toml" --points 4 --progress; then
    cp "$dir/out" "$dir/with-progress"
    run no-progress-physical 0 curve "$data/steel-rollers.toml" --points 4 &&
        { cmp -s "$dir/out" "$dir/with-progress" || fail "progress-physical: --progress changed stdout"; } &&
        echo "ok   progress-physical: the same CSV with and without --progress"
fi

finish

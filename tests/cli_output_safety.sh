#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Outputs are safe (issue 23, section 3): an image gnuplot could not write whole, or an output
# file the user may not write, costs exit 2 with one stderr line naming the file, and the files
# of an earlier run stay as they were.
#  - gnuplot exits 0 when its writes fail: on a full disk `traction`, `figure` and `convergence`
#    renamed an empty PNG and a cut SVG over the good images. A fake gnuplot first in PATH writes
#    what a full disk leaves (and worse); a tiny tmpfs makes the real gnuplot run out of space.
#  - Every output replaces its path by rename, which needs only the folder to be writable: a
#    0444 file, or another user's, was replaced where `> FILE` fails. Root may write any file,
#    so these rows run as nobody (`run_under`, cli_lib.sh).
# Usage: cli_output_safety.sh path/to/roughroll
set -u
# bin, dir, fail, expect, run_under, good_scene, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"
mounted=""
trap '[ -n "$mounted" ] && umount "$mounted"; rm -rf "$dir"' EXIT

printf '%s\n' "$good_scene" >"$dir/good.toml"

# The three commands that plot, each with the stem of its images in folder $2 (small and fast).
plot_command() {  # plot_command traction|figure|convergence FOLDER: sets cmd and stem
    case $1 in
        traction) cmd=(traction "$dir/good.toml" --points 5 --name x --out "$2"); stem="$2/traction-x" ;;
        figure) cmd=(figure 2a --points 2 --out "$2"); stem="$2/fig2a" ;;
        convergence) cmd=(convergence "$dir/good.toml" --max-seconds 0.001 --out "$2"); stem="$2/convergence-good" ;;
    esac
}

# The earlier run's images, to be kept: any content, compared byte for byte afterwards.
old_images() {  # old_images STEM
    printf 'earlier svg\n' >"$1.svg"
    printf 'earlier png\n' >"$1.png"
}

holds() {  # holds FILE TEXT: FILE is the line TEXT, byte for byte (an image may hold NUL bytes)
    printf '%s\n' "$2" | cmp -s - "$1"
}

# kept NAME FOLDER STEM: the earlier images unchanged, no temporary file left in FOLDER.
kept() {
    holds "$3.svg" "earlier svg" || fail "$1: the earlier SVG was replaced"
    holds "$3.png" "earlier png" || fail "$1: the earlier PNG was replaced"
    local left
    left=$(ls -A "$2" | grep -c '\.tmp-')
    [ "$left" -eq 0 ] || fail "$1: temporary files left: $(ls -A "$2" | tr '\n' ' ')"
}

# --- A fake gnuplot: `gnuplot -e "out='STEM'" SCRIPT` writes STEM.svg and STEM.png as $FAKE says.
mkdir -p "$dir/fake"
cat >"$dir/fake/gnuplot" <<'EOF'
#!/bin/sh
stem=${2#out=\'}
stem=${stem%\'}
svg='<?xml version="1.0"?>
<svg width="10" height="10" xmlns="http://www.w3.org/2000/svg">
<g><path d="M0,0 L10,10"/></g>
</svg>'
png() {  # the PNG signature, an IHDR chunk, and the IEND chunk unless $1 = cut
    printf '\211PNG\r\n\032\n\000\000\000\015IHDR\000\000\000\001\000\000\000\001\010\002\000\000\000\220wS\336'
    [ "$1" = cut ] || printf '\000\000\000\000IEND\256B`\202'
}
case $FAKE in
    full-disk) printf '%s' "$svg" | head -c 60 >"$stem.svg"; : >"$stem.png" ;;  # what ENOSPC left
    png-empty) printf '%s\n' "$svg" >"$stem.svg"; : >"$stem.png" ;;
    png-cut) printf '%s\n' "$svg" >"$stem.svg"; png cut >"$stem.png" ;;
    svg-cut) printf '%s' "$svg" | head -c 100 >"$stem.svg"; png >"$stem.png" ;;
    png-missing) printf '%s\n' "$svg" >"$stem.svg" ;;
    fails) printf '%s' "$svg" | head -c 60 >"$stem.svg"; echo 'gnuplot: cannot write: No space left on device'; exit 1 ;;
    whole) printf '%s\n\n' "$svg" >"$stem.svg"; png >"$stem.png" ;;
esac
exit 0
EOF
chmod 755 "$dir/fake/gnuplot"

# fake_case COMMAND MODE FILE REASON: exit 2, one stderr line naming STEM.FILE (or the
# script, when gnuplot fails) and REASON, the earlier images kept, no temporary left.
fake_case() {
    local command=$1 mode=$2 ext=$3 reason=$4 o="$dir/fake-$1-$2"
    mkdir -p "$o"
    plot_command "$command" "$o"
    old_images "$stem"
    FAKE=$mode PATH="$dir/fake:$PATH" timeout "${hang_guard:-900}" "$bin" "${cmd[@]}" >"$dir/out" 2>"$dir/err"
    local status=$?
    if [ "$status" -ne 2 ] || [ "$(wc -l <"$dir/err")" -ne 1 ] || ! grep -qF -- "$stem$ext'" "$dir/err" ||
        ! grep -qF -- "$reason" "$dir/err"; then
        fail "$command $mode: status $status, expected 2 and one line naming $stem$ext with '$reason':"
        sed 's/^/    /' "$dir/err"
    else
        echo "ok   $command $mode: $(cat "$dir/err")"
    fi
    kept "$command $mode" "$o" "$stem"
}

for command in traction figure convergence; do
    fake_case "$command" full-disk .svg "does not end with </svg>"
done
fake_case traction png-empty .png "gnuplot wrote an empty image"
fake_case traction png-cut .png "no IEND chunk"
fake_case traction svg-cut .svg "does not end with </svg>"
fake_case traction png-missing .png "gnuplot wrote no such image"
fake_case traction fails .gp "No space left on device"

# Whole images are taken: the check refuses only what is incomplete.
o="$dir/fake-whole"
mkdir -p "$o"
plot_command traction "$o"
old_images "$stem"
if FAKE=whole PATH="$dir/fake:$PATH" "$bin" "${cmd[@]}" >"$dir/out" 2>"$dir/err" &&
    [ "$(tail -c 12 "$stem.png" | od -An -c | tr -d ' \n')" = '\0\0\0\0IEND256B`202' ] &&
    grep -q '</svg>' "$stem.svg"; then
    echo "ok   traction whole: the images are replaced"
else
    fail "traction whole: $(cat "$dir/err"); $(ls -A "$o" | tr '\n' ' ')"
fi

# --- The real gnuplot: its images pass the check; on a full tmpfs they fail it.
if command -v gnuplot >/dev/null; then
    o="$dir/real"
    mkdir -p "$o"
    plot_command traction "$o"
    if "$bin" "${cmd[@]}" >"$dir/out" 2>"$dir/err" && [ -s "$stem.svg" ] && [ -s "$stem.png" ]; then
        echo "ok   traction with gnuplot: images written"
    else
        fail "traction with gnuplot: $(cat "$dir/err")"
    fi
    # 160 KiB: the CSV, the script and the earlier images fit, the new SVG (about 250 KiB) does not.
    mkdir -p "$dir/tiny"
    if [ "$(id -u)" -eq 0 ] && mount -t tmpfs -o size=160k tmpfs "$dir/tiny" 2>/dev/null; then
        mounted="$dir/tiny"
        plot_command traction "$dir/tiny"
        old_images "$stem"
        "$bin" "${cmd[@]}" >"$dir/out" 2>"$dir/err"
        status=$?
        if [ "$status" -ne 2 ] || [ "$(wc -l <"$dir/err")" -ne 1 ] || ! grep -qF "$stem." "$dir/err"; then
            fail "traction on a full tmpfs: status $status, expected 2 and one line naming an image:"
            sed 's/^/    /' "$dir/err"
        else
            echo "ok   traction on a full tmpfs: $(cat "$dir/err")"
        fi
        kept "traction on a full tmpfs" "$dir/tiny" "$stem"
        umount "$dir/tiny" && mounted=""
    else
        echo "skipped traction on a full tmpfs: cannot mount a tmpfs (not root, or not allowed here)"
    fi
else
    echo "skipped real gnuplot rows: no gnuplot"
fi

# --- Write-protected outputs: refused before any work, the file unchanged.
if [ "$(id -u)" -ne 0 ]; then
    run_under=()
elif chmod 711 "$dir" && setpriv --reuid=65534 --regid=65534 --clear-groups "$bin" --help >/dev/null 2>&1; then
    run_under=(setpriv --reuid=65534 --regid=65534 --clear-groups)
else
    echo "skipped write-protected outputs: running as root and cannot run $bin as nobody"
    echo "$failures failure(s)"
    [ "$failures" -eq 0 ]
    exit
fi
me=$(${run_under[@]+"${run_under[@]}"} id -u)
w="$dir/w"  # a folder the user may write in: rename could replace any file in it
mkdir -p "$w"
chmod 777 "$w"
readonly_file() {  # readonly_file PATH: a file the user cannot write (0444, the user's own)
    printf 'earlier\n' >"$1"
    [ "$(id -u)" -eq 0 ] && chown "$me" "$1"
    chmod 444 "$1"
}

readonly_file "$w/own.csv"
expect curve-csv-0444 "$w/own.csv': the file exists and is not writable" -- curve "$dir/good.toml" --points 3 --csv "$w/own.csv"
holds "$w/own.csv" earlier || fail "curve-csv-0444: the file was replaced"
if [ "$(id -u)" -eq 0 ]; then
    # Another user's file (root's, 0644): nobody may not write it, so neither may roughroll.
    printf 'earlier\n' >"$w/root.csv"
    chmod 644 "$w/root.csv"
    expect curve-csv-other-user "$w/root.csv': the file exists and is not writable" -- curve "$dir/good.toml" --points 3 --csv "$w/root.csv"
    holds "$w/root.csv" earlier || fail "curve-csv-other-user: the file was replaced"
fi
# Each plotting command: a write-protected image is refused before any work (no CSV written).
for command in traction figure convergence; do
    mkdir -p "$w/$command"
    chmod 777 "$w/$command"
    plot_command "$command" "$w/$command"
    readonly_file "$stem.png"
    expect "$command-png-0444" "$stem.png': the file exists and is not writable" -- "${cmd[@]}"
    [ -e "$stem.csv" ] && fail "$command-png-0444: the CSV was written: the check came after the work"
    holds "$stem.png" earlier || fail "$command-png-0444: the image was replaced"
done
mkdir -p "$w/table"
chmod 777 "$w/table"
readonly_file "$w/table/fig2a-table.md"
expect figure-table-0444 "fig2a-table.md': the file exists and is not writable" -- figure 2a --points 2 --out "$w/table" --no-plot
[ -e "$w/table/fig2a.csv" ] && fail "figure-table-0444: the CSV was written: the check came after the work"
# A file the user may write is replaced as before.
printf 'earlier\n' >"$w/mine.csv"
[ "$(id -u)" -eq 0 ] && chown "$me" "$w/mine.csv"
if ${run_under[@]+"${run_under[@]}"} "$bin" curve "$dir/good.toml" --points 3 --csv "$w/mine.csv" >"$dir/out" 2>"$dir/err" &&
    grep -q '^Q,' "$w/mine.csv"; then
    echo "ok   curve-csv-writable: replaced"
else
    fail "curve-csv-writable: $(cat "$dir/err")"
fi
run_under=()

finish

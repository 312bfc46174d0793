#!/usr/bin/env bash
# Every kind of bad input makes `roughroll` exit 2 with exactly one line on stderr that
# names the problem, and nothing on stdout. Usage: cli_bad_input.sh path/to/roughroll
set -u
bin=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0

# expect NAME KEYWORD -- ARGS...: exit 2, one stderr line containing KEYWORD, empty stdout.
expect() {
    local name=$1 keyword=$2
    shift 3
    timeout 60 "$bin" "$@" >"$dir/out" 2>"$dir/err"
    local status=$? lines
    lines=$(wc -l <"$dir/err")
    if [ "$status" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -qiF -- "$keyword" "$dir/err" || [ -s "$dir/out" ]; then
        echo "FAIL $name: status $status, $lines stderr line(s), expected '$keyword':"
        sed 's/^/    /' "$dir/err"
        failures=$((failures + 1))
    else
        echo "ok   $name: $(cat "$dir/err")"
    fi
}

scene() {  # scene NAME CONTENT: writes $dir/NAME.toml
    printf '%s\n' "$2" >"$dir/$1.toml"
}

good='friction = 0.3
Q = 0.15
[cylinder1.tangential]
T = 0.5
A = 0.5
[cylinder1.normal]
T = 0.5
A = 0.5
[solver]
n = 20'
scene good "$good"
scene noQ "$(printf '%s\n' "$good" | grep -v '^Q =')"
scene malformed 'friction = '
scene truncated "$(printf '%s\n' "$good" | head -c 40)"
scene wrongtype 'friction = "high"'
scene unknownkey "$(printf '%s\nfrction = 0.3' "$good")"
scene unknownnested "$(printf '%s\n' "$good" | sed 's/^A = 0.5$/Ax = 0.5/' )"
scene unknowntable "$(printf '%s\n[cylinder3.normal]\nT = 1\nA = 1' "$good")"
scene fzero 'friction = 0.0'
scene fneg 'friction = -0.3'
scene fnan 'friction = nan'
scene Qnan "$(printf '%s\n' "$good" | sed 's/^Q = 0.15/Q = nan/')"
scene Qbig "$(printf '%s\n' "$good" | sed 's/^Q = 0.15/Q = 0.31/')"
scene Tneg "$(printf '%s\n' "$good" | sed '0,/^T = 0.5/s//T = -0.5/')"
scene Ainf "$(printf '%s\n' "$good" | sed '0,/^A = 0.5/s//A = inf/')"
scene Anan "$(printf '%s\n' "$good" | sed '0,/^A = 0.5/s//A = nan/')"
scene nbig "$(printf '%s\n' "$good" | sed 's/^n = 20/n = 100000000/')"
scene nsmall "$(printf '%s\n' "$good" | sed 's/^n = 20/n = 1/')"
scene nfloat "$(printf '%s\n' "$good" | sed 's/^n = 20/n = 20.5/')"
scene method "$(printf '%s\nmethod = "spectral"' "$good")"
scene stiff "$(printf '%s\n' "$good" | sed 's/^A = 0.5$/A = 1000/; s/^n = 20/n = 20\nmethod = "paper"/')"

expect missing-file "cannot read" -- point "$dir/nope.toml"
expect directory "cannot read" -- point "$dir"
expect malformed-toml "malformed" -- point "$dir/malformed.toml"
expect truncated-toml "malformed" -- point "$dir/truncated.toml"
expect wrong-type "friction" -- point "$dir/wrongtype.toml"
expect unknown-key "frction" -- point "$dir/unknownkey.toml"
expect unknown-nested-key "Ax" -- point "$dir/unknownnested.toml"
expect unknown-table "cylinder3" -- point "$dir/unknowntable.toml"
expect f-zero "friction" -- point "$dir/fzero.toml" --Q 0
expect f-negative "friction" -- point "$dir/fneg.toml" --Q 0
expect f-nan "friction" -- point "$dir/fnan.toml" --Q 0
expect Q-missing "Q" -- point "$dir/noQ.toml"
expect Q-nan-scene "Q" -- point "$dir/Qnan.toml"
expect Q-nan-cli "Q" -- point "$dir/good.toml" --Q nan
expect Q-inf-cli "Q" -- point "$dir/good.toml" --Q inf
expect Q-above-f "slide" -- point "$dir/Qbig.toml"
expect Q-below-minus-f "slide" -- point "$dir/good.toml" --Q -0.3000001
expect T-negative "T" -- point "$dir/Tneg.toml"
expect A-infinite "A" -- point "$dir/Ainf.toml"
expect A-nan "A" -- point "$dir/Anan.toml"
expect n-huge "n" -- point "$dir/nbig.toml"
expect n-small "n" -- point "$dir/nsmall.toml"
expect n-float "n" -- point "$dir/nfloat.toml"
expect n-cli "outside" -- point "$dir/good.toml" --n 5000
expect n-cli-negative "outside" -- point "$dir/good.toml" --n -3
expect method-scene "spectral" -- point "$dir/method.toml"
expect method-cli "spectral" -- point "$dir/good.toml" --method spectral
expect beyond-resolution "resolution" -- point "$dir/stiff.toml"
expect curve-points "points" -- curve "$dir/good.toml" --points 1
expect curve-unwritable "cannot write" -- curve "$dir/good.toml" --points 3 --csv "$dir/no/such/dir/x.csv"
expect unknown-option "--frobnicate" -- point "$dir/good.toml" --frobnicate
expect no-subcommand "subcommand" --
expect figure-unknown "2c" -- figure 2c

# A valid scene must still work (the harness above is not failing everything).
if ! "$bin" point "$dir/good.toml" --json >"$dir/out" 2>"$dir/err" || ! grep -q '"xi"' "$dir/out"; then
    echo "FAIL the valid scene did not solve:"; cat "$dir/err"; failures=$((failures + 1))
fi

echo "$failures failure(s)"
[ "$failures" -eq 0 ]

# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by the shell tests of tests/ that run the program (cli_*.sh, readme_example.sh), which
# CTest and `make check` call with the program as their first argument: the lines they share.
#   bin          $1 as an absolute path (some rows run in another folder)
#   src, data    the source tree (the folder above tests/) and its data/
#   dir          a temporary folder, removed at exit (a test with more to clean up sets its own
#                EXIT trap, removing "$dir" too)
#   failures     the count of failed checks; fail MESSAGE... prints "FAIL MESSAGE" and counts one
#   hang_guard   the seconds `timeout` gives one call: a guard against hangs, not a speed limit;
#                the slowest call of these tests takes a few seconds in Release and under a minute
#                with the sanitizers on a loaded machine (docs/robustness.md)
#   expect NAME KEYWORD -- ARGS...  the one check of a bad input: `$bin ARGS` exits 2 with one
#                stderr line containing KEYWORD (case-insensitive) and nothing on stdout; run under
#                the command in the array `run_under` when it is set (another user, another PATH),
#                its stdout to the file `stdout_to` when that is set (then not checked empty)
#   good_scene, stiff_scene  the scenes several tests write: a small rough scene that solves
#                (n = 20), and a very stiff normal layer at n = 16 whose curve has refused rows
#   finish       prints the count of failures and exits with status 0 only when there is none
[ $# -ge 1 ] || { echo "usage: $0 path/to/roughroll ..." >&2; exit 2; }
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
data=$src/data
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
hang_guard=${ROUGHROLL_HANG_GUARD:-900}

run_under=()
stdout_to=""
expect() {
    local name=$1 keyword=$2 out=${stdout_to:-$dir/out}
    shift 3
    rm -f "$dir/out"
    timeout "$hang_guard" ${run_under[@]+"${run_under[@]}"} "$bin" "$@" >"$out" 2>"$dir/err"
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

good_scene='friction = 0.3
Q = 0.15
[cylinder1.tangential]
T = 0.5
A = 0.5
[cylinder1.normal]
T = 0.5
A = 0.5
[solver]
n = 20'

stiff_scene='friction = 0.3
Q = 0.15
[cylinder2.normal]
T = 1e6
A = 1
[solver]
n = 16
method = "product"'

finish() {
    echo "$failures failure(s)"
    exit $((failures > 0))
}

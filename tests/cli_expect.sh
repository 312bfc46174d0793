# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by the CLI tests (cli_bad_input.sh, cli_roughness.sh): the one check of a bad input.
# expect NAME KEYWORD -- ARGS...: `$bin ARGS` exits 2 with one stderr line containing KEYWORD
# (case-insensitive) and nothing on stdout. Needs $bin, $dir and $failures from the caller;
# runs the program under the command in the array `as_user` when it is set.
as_user=()
# A guard against hangs, not a speed limit: the slowest call of the CLI tests takes a few
# seconds in Release and under a minute with the sanitizers on a loaded machine (docs/robustness.md).
hang_guard=${ROUGHROLL_HANG_GUARD:-900}
expect() {
    local name=$1 keyword=$2
    shift 3
    timeout "$hang_guard" ${as_user[@]+"${as_user[@]}"} "$bin" "$@" >"$dir/out" 2>"$dir/err"
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

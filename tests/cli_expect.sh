# Sourced by the CLI tests (cli_bad_input.sh, cli_roughness.sh): the one check of a bad input.
# expect NAME KEYWORD -- ARGS...: `$bin ARGS` exits 2 with one stderr line containing KEYWORD
# (case-insensitive) and nothing on stdout. Needs $bin, $dir and $failures from the caller;
# runs the program under the command in the array `as_user` when it is set.
as_user=()
expect() {
    local name=$1 keyword=$2
    shift 3
    timeout 60 ${as_user[@]+"${as_user[@]}"} "$bin" "$@" >"$dir/out" 2>"$dir/err"
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

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The README's C++ program compiles and tells the truth (issue 25, item 6): extracts the one
# fenced ```cpp block of README.md, compiles it against the source tree's headers (it includes
# only roughroll/roughroll.hpp) and the library just built, runs it on data/fig2a-T1.toml and
# checks that its c0, xi and P_H/P2 are those of `roughroll point data/fig2a-T1.toml --json`
# (the same build), digit for digit, that the README shows that very output (the first fenced
# block after the cpp block), and that it exits 2 with one line on a missing file.
# Usage: readme_example.sh PROGRAM LIBRARY [CXX [CXXFLAGS]]
#   PROGRAM   the roughroll program of the same build
#   LIBRARY   the library file (libroughroll_core.a, or the shared one)
#   CXX       the C++ compiler, with any words of its own (default c++); CXXFLAGS the build's
#             flags (sanitizers included)
set -u
[ $# -ge 2 ] || { echo "usage: $0 PROGRAM LIBRARY [CXX [CXXFLAGS]]" >&2; exit 2; }
# bin, src, dir, fail, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"
lib=$2
cxx=${3:-c++}
cxxflags=${4:-}

# --- The one ```cpp block of the README.
awk '/^```cpp[[:space:]]*$/ { n++; inside = 1; next } /^```/ { inside = 0 } inside { print }
     END { if (n != 1) { print "README.md has " n " cpp blocks, not 1" > "/dev/stderr"; exit 1 } }' \
    "$src/README.md" >"$dir/example.cpp" || { echo "FAIL extracting the cpp block"; exit 1; }
echo "ok   README.md's cpp block: $(wc -l <"$dir/example.cpp") lines"
if grep -n '#include *"roughroll/' "$dir/example.cpp" | grep -v 'roughroll/roughroll\.hpp' >/dev/null; then
    fail "the example includes another roughroll header than roughroll/roughroll.hpp"
fi

# --- Compile and link it: the static library's dependencies (GSL, toml++) from pkg-config.
libs=$(pkg-config --libs gsl tomlplusplus 2>/dev/null) || libs="-lgsl -lgslcblas -lm -ltomlplusplus"
# shellcheck disable=SC2086  # CXXFLAGS and the libraries are lists of words
# CXX may hold words of its own (autoconf's "g++ -std=c++17").
read -r -a compiler <<<"$cxx"
if ! "${compiler[@]}" -std=c++17 $cxxflags -I"$src/include" "$dir/example.cpp" -o "$dir/example" \
        "$lib" -Wl,-rpath,"$(cd "$(dirname "$lib")" && pwd)" $libs >"$dir/compile.log" 2>&1; then
    cat "$dir/compile.log"
    echo "FAIL the README's example does not compile"
    exit 1
fi
echo "ok   compiled against $src/include and $lib"

# --- Run it on Fig. 2a's curve 3 and compare with the program's JSON.
if ! "$dir/example" "$src/data/fig2a-T1.toml" >"$dir/out" 2>"$dir/err"; then
    fail "the example failed on data/fig2a-T1.toml: $(cat "$dir/err")"
fi
cat "$dir/out"
# The README shows that output in the first fenced block after the cpp block: the same text.
awk '/^```cpp[[:space:]]*$/ { after = 1; next } after == 1 && /^```/ { after = 2; next }
     after == 2 && /^```/ { if (inside) exit; inside = 1; next } inside { print }' \
    "$src/README.md" >"$dir/shown"
if diff -u "$dir/shown" "$dir/out" >"$dir/diff"; then
    echo "ok   the README shows this output"
else
    fail "the README shows another output than the example prints:"; cat "$dir/diff"
fi
if ! "$bin" point "$src/data/fig2a-T1.toml" --json >"$dir/json" 2>"$dir/err"; then
    fail "roughroll point --json failed: $(cat "$dir/err")"
fi
# value FILE KEY: the word after "KEY" at the start of a line of the example's output.
value() { awk -v k="$2" '$1 == k { print $2; exit }' "$1"; }
# json KEY: the top-level number KEY of the program's JSON, in the shortest text that reads back.
json() {
    python3 -c 'import json, sys; print(repr(float(json.load(open(sys.argv[1]))[sys.argv[2]])))' "$dir/json" "$1"
}
for pair in "c0 c0" "xi xi" "P_H/P2 hertz_load_ratio"; do
    read -r name key <<<"$pair"
    got=$(value "$dir/out" "$name")
    want=$(json "$key")
    if [ -n "$got" ] && [ "$got" = "$want" ]; then
        echo "ok   $name $got, as roughroll point --json"
    else
        fail "$name: the example prints '$got', roughroll point --json gives '$want'"
    fi
done

# --- A missing file: exit 2 and one line on stderr.
"$dir/example" "$dir/no-such.toml" >"$dir/out" 2>"$dir/err"
status=$?
if [ "$status" -eq 2 ] && [ "$(wc -l <"$dir/err")" -eq 1 ]; then
    echo "ok   a missing file: exit 2, $(cat "$dir/err")"
else
    fail "a missing file: status $status, stderr '$(cat "$dir/err")'"
fi

finish

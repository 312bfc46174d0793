#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The CMake build and the autotools build compile the same .cpp files: compares the sources
# of the library (roughroll_core), the program (roughroll), the test programs (every
# add_executable of tests/ and validation/, `foreach(name ...)` lists expanded) and the shell
# tests of tests/CMakeLists.txt with those of Makefile.am, and prints the differences. The
# installed headers too: CMake installs ROUGHROLL_PUBLIC_HEADERS, Makefile.am its roughroll_*_HEADERS
# lists, and a header missing there breaks `make install` consumers; and every include/roughroll/**.hpp
# is in one of Makefile.am's *_HEADERS (installed or noinst_HEADERS), or `make dist` leaves it out.
# Usage: build_sources_match.sh [SOURCE_DIR]   (default: the directory above this script)
set -euo pipefail
src=${1:-"$(dirname "$0")/.."}
cd "$src"
for f in CMakeLists.txt tests/CMakeLists.txt validation/CMakeLists.txt Makefile.am; do
    [ -f "$f" ] || { echo "FAIL: $src/$f not found"; exit 1; }
done

# flat FILE: the file without comments, on one line (lists may span lines).
flat() { sed 's/#.*//' "$1" | tr '\n\t' '  '; }

# words TEXT: one word per line.
words() { printf '%s\n' "$1" | tr -s ' ' '\n' | sed '/^$/d'; }

# call TEXT COMMAND NAME: the arguments of the first COMMAND(NAME ...) in TEXT.
call() {
    printf '%s\n' "$1" | grep -oE "$2\\([[:space:]]*$3[[:space:]][^)]*\\)" | head -n 1 |
        sed -E "s/^$2\\([[:space:]]*$3[[:space:]]//; s/\\)\$//" || true
}

# Sources of every add_executable of DIR/CMakeLists.txt, as "test DIR/FILE.cpp", with
# add_executable inside a foreach(VAR ITEMS...) expanded for each item.
cmake_tests() {
    local dir=$1 chunk before loop header var items body exe item s
    # One chunk per loop: "text before; foreach(...) body" (the endforeach dropped).
    while IFS= read -r chunk; do
        before=${chunk%%foreach(*}
        for s in $(printf '%s\n' "$before" | grep -oE 'add_executable\([^)]*\)' | sed 's/^add_executable(//; s/)$//' |
                   tr -s ' ' '\n' | grep '\.cpp$' || true); do
            echo "test $dir/$s"
        done
        [ "$before" = "$chunk" ] && continue
        loop=${chunk#*foreach(}
        header=${loop%%)*}
        body=${loop#*)}
        read -r var items <<<"$header"
        items=${items#IN ITEMS }
        for exe in $(printf '%s\n' "$body" | grep -oE 'add_executable\([^)]*\)' | sed 's/^add_executable(//; s/)$//' |
                     tr -s ' ' '\n' | grep '\.cpp$' || true); do
            for item in $items; do
                echo "test $dir/${exe//"\${$var}"/$item}"
            done
        done
    done < <(flat "$dir/CMakeLists.txt" | sed 's/endforeach[[:space:]]*([^)]*)/\n/g')
}

cmake_list() {
    local top
    top=$(flat CMakeLists.txt)
    words "$(call "$top" add_library roughroll_core)" | grep '\.cpp$' | sed 's/^/library /'
    words "$(call "$top" add_executable roughroll)" | grep '\.cpp$' | sed 's/^/program /'
    cmake_tests tests
    cmake_tests validation
    # Shell tests: ${CMAKE_CURRENT_SOURCE_DIR}/NAME.sh in tests/CMakeLists.txt.
    flat tests/CMakeLists.txt | grep -oE '\$\{CMAKE_CURRENT_SOURCE_DIR\}/[A-Za-z0-9_.-]+\.sh' |
        sed 's|^${CMAKE_CURRENT_SOURCE_DIR}/|script tests/|'
    # set(ROUGHROLL_PUBLIC_HEADERS ...): the installed headers.
    words "$(call "$top" set ROUGHROLL_PUBLIC_HEADERS)" | grep '\.hpp$' | sed 's/^/header /'
    # Every header of the tree, for the distribution.
    find include/roughroll -name '*.hpp' | sed 's/^/dist /'
}

# Makefile.am with continuation lines joined and comments removed: VAR = VALUE per line.
am_flat() { sed -e 's/#.*//' -e ':a' -e '/\\$/{N; s/\\\n/ /; ta' -e '}' Makefile.am | tr '\t' ' '; }

# am_values REGEX: the words of every assignment (= or +=) to a variable matching REGEX.
am_values() {
    am_flat | grep -E "^ *($1) *\\+?=" | sed -E 's/^[^=]*=//' | tr -s ' ' '\n' | sed '/^$/d' || true
}

am_list() {
    am_values 'libroughroll_core_l?a_SOURCES' | grep '\.cpp$' | sed 's/^/library /'
    am_values 'roughroll_SOURCES' | grep '\.cpp$' | sed 's/^/program /'
    am_values '(tests|validation)_[A-Za-z0-9_]+_SOURCES' | grep '\.cpp$' | sed 's/^/test /'
    # Shell tests: every tests/*.sh in the variables of TESTS (one level of $(VAR)).
    local v
    for v in $(am_values 'TESTS'); do
        case $v in
            \$\(*\)) v=${v#\$\(}; am_values "${v%\)}" ;;
            *) echo "$v" ;;
        esac
    done | grep -E '^tests/.*\.sh$' | sed 's/^/script /'
    am_values 'roughroll_[a-z]+_HEADERS' | grep '^include/roughroll/.*\.hpp$' | sed 's/^/header /'
    am_values '[A-Za-z0-9_]+_HEADERS' | grep '^include/roughroll/.*\.hpp$' | sed 's/^/dist /'
}

# What the CMake build and its tests read besides the files compared below: every script and file of tests/ (the shell
# tests, install_consumer.sh, installed_headers.sh, the consumer), configure_file's inputs and each add_subdirectory's
# CMakeLists.txt. Each must be in Makefile.am's distribution (EXTRA_DIST or the shell tests, as a file or inside a
# listed folder), or the tarball of `make dist` does not build with CMake (`shipped` below).
cmake_reads() {
    local top
    top=$(flat CMakeLists.txt)
    find tests -type f \( -name '*.sh' -o -name '*.py' -o -path 'tests/consumer/*' \)
    printf '%s\n' "$top" | grep -oE 'configure_(package_config_)?file\([[:space:]]*[^ )$]+' | sed -E 's/^[^(]*\([[:space:]]*//'
    printf '%s\n' "$top" | grep -oE 'add_subdirectory\([[:space:]]*[^ )]+' | sed -E 's/^[^(]*\([[:space:]]*//; s|$|/CMakeLists.txt|'
}
am_dist() {
    local v
    for v in $(am_values 'EXTRA_DIST'); do
        case $v in
            \$\(*\)) v=${v#\$\(}; am_values "${v%\)}" ;;
            *) echo "$v" ;;
        esac
    done
}
dist_list=$(am_dist)
not_shipped=""
while IFS= read -r f; do
    shipped=no
    while IFS= read -r d; do
        [ "$f" = "$d" ] || [ "${f#"$d"/}" != "$f" ] && { shipped=yes; break; }
    done <<<"$dist_list"
    [ "$shipped" = yes ] || not_shipped+="    $f"$'\n'
done < <(cmake_reads | sort -u)

cmake=$(cmake_list | sort -u)
am=$(am_list | sort -u)
status=0
for kind in library program test script header dist; do
    if ! grep -q "^$kind " <<<"$cmake"; then
        echo "FAIL: no $kind sources found in the CMake files"; status=1
    fi
    if ! grep -q "^$kind " <<<"$am"; then
        echo "FAIL: no $kind sources found in Makefile.am"; status=1
    fi
done
only_cmake=$(comm -23 <(echo "$cmake") <(echo "$am"))
only_am=$(comm -13 <(echo "$cmake") <(echo "$am"))
if [ -n "$only_cmake" ]; then
    echo "FAIL: only in CMakeLists.txt (tests/, validation/):"; sed 's/^/    /' <<<"$only_cmake"; status=1
fi
if [ -n "$only_am" ]; then
    echo "FAIL: only in Makefile.am:"; sed 's/^/    /' <<<"$only_am"; status=1
fi
if [ -n "$not_shipped" ]; then
    echo "FAIL: read by the CMake build or its tests, not in Makefile.am's EXTRA_DIST (make dist leaves it out):"
    printf '%s' "$not_shipped"; status=1
fi
if [ "$status" -eq 0 ]; then
    echo "ok: CMake and Makefile.am build the same $(wc -l <<<"$cmake") files:"
    sed 's/^/    /' <<<"$cmake"
fi
exit "$status"

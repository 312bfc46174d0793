#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The installed headers are closed: every roughroll header an installed header includes is installed
# too (issue 24, 9: the solvers' and numerics' headers stay in the source tree). Walks the #include
# lines of every header under INCLUDE_DIR/roughroll ("roughroll/..." or <roughroll/...>) and fails
# (non-zero), naming the header and what it includes, on one that INCLUDE_DIR does not hold; a
# consumer would meet it as "No such file" only where it happens to include that header.
# Usage: tests/installed_headers.sh INCLUDE_DIR   (install_consumer.sh: the CMake install;
#        scripts/test: the autotools install)
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 INCLUDE_DIR" >&2; exit 2; }
dir=$1
[ -f "$dir/roughroll/roughroll.hpp" ] || { echo "installed_headers: $dir/roughroll/roughroll.hpp not installed" >&2; exit 1; }
status=0
count=0
while IFS= read -r header; do
    count=$((count + 1))
    while IFS= read -r included; do
        [ -f "$dir/$included" ] && continue
        echo "installed_headers: ${header#"$dir"/} includes $included, which is not installed" >&2
        status=1
    done < <(sed -nE 's@^[[:space:]]*#[[:space:]]*include[[:space:]]*["<](roughroll/[^">]+)[">].*@\1@p' "$header")
done < <(find "$dir/roughroll" -type f -name '*.hpp' | sort)
[ "$status" -eq 0 ] && echo "installed_headers: the $count installed headers include only installed ones"
exit "$status"

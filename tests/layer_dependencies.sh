#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Dependencies point one way, from the command line down to the mathematics. The layers, from
# the bottom (src/LAYER and include/roughroll/LAYER, the same names in both trees):
#   base      errors, GSL handles, number formatting
#   layer     the paper's Sec. 2: the rough layer's micro-geometry and its parameters (2.6)-(2.14)
#   model     Sec. 3: roughness (3.26), kernels (3.23)-(3.24), Carter, physical scenes
#   numerics  quadrature, kernel moments and sweeps, collocation (4.1)-(4.8), linear systems, roots
#   problems  the normal, tangential and one-parameter problems, the contact, the contact width
#   io        scene files, micro-geometry specs, profile CSVs, JSON/text output
#   cli       the command line (src/cli only)
# A file may include headers of its own layer and of the layers below it. layer and model are
# side by side: neither includes the other. Prints every include that points up or sideways.
# Usage: layer_dependencies.sh [SOURCE_DIR]
set -euo pipefail
cd "${1:-"$(dirname "$0")/.."}"
layers=(base layer model numerics problems io cli)
rank() {
    local i
    for i in "${!layers[@]}"; do [ "${layers[$i]}" = "$1" ] && { echo "$i"; return; }; done
    echo -1
}
allowed() {  # allowed FROM TO
    [ "$1" = "$2" ] && return 0
    [ "$1" = layer ] && [ "$2" = model ] && return 1
    [ "$1" = model ] && [ "$2" = layer ] && return 1
    [ "$(rank "$2")" -lt "$(rank "$1")" ]
}
status=0 count=0
while IFS= read -r file; do
    from=$(sed -E 's#^(src|include/roughroll)/([a-z]+)/.*#\2#' <<<"$file")
    # The umbrella header roughroll/roughroll.hpp (the public interface in one include) sits
    # at the io layer's height: it may include io and everything below it, never cli.
    [ "$file" = include/roughroll/roughroll.hpp ] && from=io
    if [ "$(rank "$from")" -lt 0 ]; then
        echo "FAIL: $file is in no layer (folders: ${layers[*]})"; status=1; continue
    fi
    while IFS= read -r inc; do
        to=$(sed -E 's#^(roughroll/)?([a-z]+)/.*#\2#' <<<"$inc")
        [ "$(rank "$to")" -lt 0 ] && continue  # a header of the same folder, included by its name
        count=$((count + 1))
        if ! allowed "$from" "$to"; then
            echo "FAIL: $file ($from) includes $inc ($to)"; status=1
        fi
    done < <(grep -oE '^#include "[^"]+"' "$file" | sed -E 's/^#include "(.*)"/\1/')
done < <(find src include/roughroll -name '*.[ch]pp' | sort)
outside=$(find src include/roughroll -maxdepth 1 -name '*.[ch]pp' ! -path include/roughroll/roughroll.hpp)
[ -z "$outside" ] || { echo "FAIL: files outside the layer folders:"; echo "$outside"; status=1; }
[ "$status" -eq 0 ] && echo "ok: $count includes, every one down a layer or within one"
exit "$status"

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs an already-built roughroll into a temporary prefix, checks that its headers include only
# installed ones (installed_headers.sh), and builds tests/consumer against it twice, with CMake's
# find_package(roughroll) and with pkg-config; runs both consumers.
# Fails (non-zero) when the install, a build or a consumer's check fails.
# Usage: tests/install_consumer.sh SOURCE_DIR BUILD_DIR   (CTest test install_consumer)
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 SOURCE_DIR BUILD_DIR" >&2; exit 2; }
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
version=$(head -n 1 "$src/VERSION")
work=$(mktemp -d "${TMPDIR:-/tmp}/roughroll-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

echo "== cmake --install $build --prefix $prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log" || { cat "$work/install.log" >&2; exit 1; }
for f in bin/roughroll include/roughroll/roughroll.hpp include/roughroll/problems/contact.hpp; do
    [ -e "$prefix/$f" ] || { echo "install_consumer: $f not installed" >&2; exit 1; }
done
# Only the public headers (CMakeLists.txt, ROUGHROLL_PUBLIC_HEADERS): the solvers' and numerics' stay here.
for f in include/roughroll/problems/point_model.hpp include/roughroll/problems/level_store.hpp \
         include/roughroll/problems/tangential_problem.hpp \
         include/roughroll/problems/contact_internals.hpp include/roughroll/numerics/collocation.hpp \
         include/roughroll/numerics/quadrature.hpp; do
    [ ! -e "$prefix/$f" ] || { echo "install_consumer: $f installed, a header of the library's own" >&2; exit 1; }
done
"$src/tests/installed_headers.sh" "$prefix/include"

echo "== CMake: find_package(roughroll $version)"
cmake -S "$src/tests/consumer" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$prefix" \
      -DROUGHROLL_EXPECTED_VERSION="$version" -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" ||
    { cat "$work/configure.log" >&2; exit 1; }
# The package must be the one just installed, not another copy on the system.
grep -q "^roughroll_DIR:PATH=$prefix/" "$work/cmake/CMakeCache.txt" ||
    { echo "install_consumer: find_package did not use $prefix" >&2; exit 1; }
cmake --build "$work/cmake"
"$work/cmake/consumer"

# roughroll.pc is in GNUInstallDirs' libdir: lib, lib64 or lib/<multiarch>.
pc=$(find "$prefix" -path '*/pkgconfig/roughroll.pc' -print -quit)
[ -n "$pc" ] || { echo "install_consumer: roughroll.pc not installed" >&2; exit 1; }
export PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
echo "== pkg-config: $(pkg-config --cflags --libs roughroll)"
[ "$(pkg-config --modversion roughroll)" = "$version" ] ||
    { echo "install_consumer: roughroll.pc has version $(pkg-config --modversion roughroll), not $version" >&2; exit 1; }
mkdir -p "$work/pkg-config"
make --no-print-directory -C "$src/tests/consumer" OUT="$work/pkg-config/consumer"
# No run path is linked in this way: a shared libroughroll_core is found through LD_LIBRARY_PATH.
LD_LIBRARY_PATH="$(dirname "$(dirname "$pc")")${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$work/pkg-config/consumer"
echo "install_consumer: both consumers pass"

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The documents users read (README.md, CHANGELOG.md, docs/*.md) hold no control characters but the
# newline: a tab or form feed in them is a TeX command (\times, \frac, \beta, \to) whose backslash an
# editing script took for an escape (session 20 found six in docs/formulation.md). Prints each line.
# Usage: docs_plain_text.sh [SOURCE_DIR]
set -euo pipefail
cd "${1:-"$(dirname "$0")/.."}"
if grep -nP '[\x00-\x09\x0b-\x1f\x7f]' README.md CHANGELOG.md docs/*.md; then
    echo "control characters in the documents above (a TeX command's backslash lost?)" >&2
    exit 1
fi

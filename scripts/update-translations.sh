#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Collects every tr() string into translations/*.ts (lupdate over the source folders; the
# CMake lupdate target would parse every included system header and takes many minutes).
# Untranslated strings fail tst_translations until they are translated.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
lupdate="$(command -v lupdate6 || echo /usr/lib/qt6/bin/lupdate)"
for ts in "$root"/translations/*.ts; do
    "$lupdate" -no-obsolete -locations none "$root/app" "$root/core" "$root/widgets" -ts "$ts"
done

#!/usr/bin/env bash
# Checks that every C++ file in git is laid out as .clang-format says (the `format` test in CI).
#   scripts/check-format.sh          lists the files that differ, exits 1 if any
#   scripts/check-format.sh --fix    reformats them in place
# Uses clang-format-14 (Debian 12's; another version may lay out some lines differently).
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$formatter" ]; then
    echo "check-format ERROR: clang-format is not installed (scripts/install-deps.sh installs it)" >&2
    exit 2
fi
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
    "$formatter" -i "${files[@]}"
    exit 0
fi
differ=0
for file in "${files[@]}"; do
    if ! "$formatter" --dry-run --Werror "$file" >/dev/null 2>&1; then
        echo "check-format ERROR: $file: not laid out as .clang-format says (scripts/check-format.sh --fix)" >&2
        differ=1
    fi
done
exit "$differ"

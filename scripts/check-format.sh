#!/usr/bin/env sh
# The repository's C++ sources follow .clang-format (Debian's clang-format 14): every tracked
# .cpp/.hpp file, checked without rewriting it. Fix with:
#   git ls-files '*.cpp' '*.hpp' | xargs clang-format -i
# Exit 77 (skipped) outside a git checkout, where the tracked files are unknown.
set -eu
cd "$(dirname "$0")/.."
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "check-format: not a git checkout; skipped"
  exit 77
fi
if ! command -v clang-format >/dev/null 2>&1; then
  echo "check-format: clang-format not found (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
files=$(git ls-files '*.cpp' '*.hpp')
# shellcheck disable=SC2086
if ! clang-format --dry-run -Werror $files; then
  echo "check-format: the files above are not formatted (see the fix at the top of $0)" >&2
  exit 1
fi
echo "check-format: $(echo "$files" | wc -l) files formatted"

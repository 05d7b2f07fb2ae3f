#!/bin/sh
# Every tracked C++ file is formatted as .clang-format says (Google, 100
# columns): fails listing the files that are not, so the style the project
# claims is the style it has.
# Usage: format_test.sh SOURCE_DIR
set -eu
cd "$1"
if ! git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  echo "not a git checkout: nothing to check"
  exit 77
fi
bad=$(git ls-files '*.cpp' '*.h' | while read -r f; do
  clang-format --dry-run --Werror "$f" > /dev/null 2>&1 || echo "$f"
done)
if [ -n "$bad" ]; then
  echo "FAIL: not formatted (clang-format -i FILE):"
  echo "$bad"
  exit 1
fi
echo "format: every C++ file follows .clang-format"

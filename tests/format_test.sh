#!/bin/sh
# Every tracked C++ file is formatted as .clang-format says (Google, 100
# columns): fails listing the files that are not, so the style the project
# claims is the style it has. clang-format runs on batches of files, two at a
# time (one process per file took over a minute of CI).
# Usage: format_test.sh SOURCE_DIR
set -eu
cd "$1"
if ! git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  echo "not a git checkout: nothing to check"
  exit 77
fi
bad=$(git ls-files -z '*.cpp' '*.h' |
  xargs -0 -P 2 -n 40 clang-format --dry-run --Werror 2>&1 >/dev/null |
  sed -n 's/^\(.*\):[0-9][0-9]*:[0-9][0-9]*: error: .*/\1/p' | sort -u)
if [ -n "$bad" ]; then
  echo "FAIL: not formatted (clang-format -i FILE):"
  echo "$bad"
  exit 1
fi
echo "format: every C++ file follows .clang-format"

#!/bin/sh
# A fresh clone is all the project needs: no tracked file may point outside
# it at the folder the thesis tables were once read from (a `shared/` beside
# the checkout); they are in tests/data/thesis/. Fails listing the offending
# lines. .ci/run proves the same by testing a clone with nothing beside it.
# Usage: self_contained_test.sh SOURCE_DIR
set -eu
cd "$1"
if ! git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  echo "not a git checkout: nothing to check"
  exit 77
fi
# ../shared, shared/reference, and the Python spelling os.path.join(.., "..", "shared", ...).
pattern='\.\./shared|shared/reference|"\.\.", *"shared"'
if git grep -nE -e "$pattern" -- . ':!tests/self_contained_test.sh'; then
  echo "FAIL: the tracked files above read outside the checkout (use tests/data/thesis/)"
  exit 1
fi
echo "self-contained: no tracked file refers to ../shared"

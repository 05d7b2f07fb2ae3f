#!/usr/bin/env bash
# The README's test command: install what is missing, build, run every test,
# then (unless HOMESH_SANITIZE=0) again under ASan/UBSan with bounded fuzzing.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
(cd "${HOMESH_BUILD_DIR:-$root/build}" && ctest --output-on-failure --no-tests=error -j "$(nproc)")
if [ "${HOMESH_SANITIZE:-1}" != 0 ]; then
  "$root/scripts/sanitize.sh"
fi

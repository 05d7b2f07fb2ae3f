#!/usr/bin/env bash
# The README's main job: install what is missing, build, and run the NACA-7526
# pipeline, printing a validity and quality summary and writing out/naca7526.msh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
mkdir -p "$root/out"
"${HOMESH_BUILD_DIR:-$root/build}/homesh" "$root/geo/naca.geo" \
  -m mesh -m curve:p=4 -m quality -m info "$root/out/naca7526.msh"

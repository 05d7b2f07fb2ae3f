#!/usr/bin/env bash
# Regenerates the thesis chapter 3 study in one command:
#   scripts/study_ch3.sh [OUTDIR]      (default out/study_ch3)
# builds homesh-study if needed (in $HOMESH_BUILD_DIR, default build/, configured
# by scripts/setup.sh; configures it here if missing), runs it (CSV tables and
# summary.md) and draws the pictures with scripts/plot_ch3.py (PNG).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOMESH_BUILD_DIR:-$root/build}"
out="${1:-$root/out/study_ch3}"

if [ ! -f "$build/build.ninja" ] && [ ! -f "$build/Makefile" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
if ! log=$(cmake --build "$build" --target homesh-study -j "$(nproc)" 2>&1); then
  echo "$log" >&2
  exit 1
fi

start=$(date +%s)
"$build/homesh-study" --out "$out" --gallery "$root/geo/gallery_t1_t12.csv" \
  --reference "$root/tests/data/thesis"
/usr/bin/python3 "$root/scripts/plot_ch3.py" "$out"
echo "study_ch3: done in $(( $(date +%s) - start )) s; read $out/summary.md"

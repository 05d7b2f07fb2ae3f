#!/usr/bin/env bash
# Installs the Debian packages homesh needs (apt-get, as root; only the missing
# ones) and builds it in build/, every warning an error (HOMESH_WERROR=OFF in
# the environment to build anyway). Idempotent: a second run only rebuilds.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOMESH_BUILD_DIR:-$root/build}"

mapfile -t wanted < <(grep -v '^\s*#' "$root/scripts/debian-packages.txt" | grep -v '^\s*$')
missing=()
for pkg in "${wanted[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done
if ((${#missing[@]})); then
  echo "homesh setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DHOMESH_WERROR="${HOMESH_WERROR:-ON}" >/dev/null
cmake --build "$build" -j "$(nproc)"

#!/usr/bin/env bash
# Configures (once) and builds Throng in Release into build/. Extra arguments go to CMake
# at configure time. Fast when nothing changed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${THRONG_BUILD_DIR:-$root/build}"
source "$root/scripts/ccache.sh"
if [ ! -f "$build/build.ninja" ] || [ $# -gt 0 ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${ccache_args[@]}" "$@" >/dev/null
fi
cmake --build "$build" -- -j"$(nproc)"

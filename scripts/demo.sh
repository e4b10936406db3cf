#!/usr/bin/env bash
# Installs what is missing, builds, and starts Throng on the crossroads demo. With no
# display it runs the headless demo instead and says where the results went.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/deps.sh" build
"$root/scripts/build.sh"
scene="$root/resources/scenes/crossroads.yaml"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$root/build/app/editor/throng" "$scene"
fi
out="$root/out/demo"
mkdir -p "$out"
echo "No display: running the headless demo." >&2
"$root/build/app/cli/throng-cli" run "$scene" --stats "$out/stats.json" \
  --trajectories "$out/trajectories.csv" --export "$out/crossroads.glb"
echo "Headless demo written to $out (stats.json, trajectories.csv, crossroads.glb)"

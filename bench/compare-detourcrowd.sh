#!/usr/bin/env bash
# Runs DetourCrowd (../shared/peers, Debian's librecast-dev) and Throng on the same
# cross/circle scenario in one go, several times, and prints one JSON object with the
# medians and the ratio. Usage: bench/compare-detourcrowd.sh [AGENTS] [STEPS] [RUNS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
agents="${1:-10000}" steps="${2:-240}" runs="${3:-3}"
peers="$root/../shared/peers"
cli="$root/build/app/cli/throng-cli"
peer_bin="${TMPDIR:-/tmp}/throng-detourcrowd-bench"

dpkg-query -W -f='${Status}' librecast-dev 2>/dev/null | grep -q "install ok installed" || {
  sudo=""; [ "$(id -u)" = 0 ] || sudo=sudo
  $sudo apt-get install -y -q librecast-dev >&2
}
[ -x "$peer_bin" ] || make -s -C "$peers" OUT="$peer_bin" >&2
[ -x "$cli" ] || "$root/scripts/build.sh" >&2

throng=() detour=()
for ((r = 0; r < runs; ++r)); do
  # Alternate the two so machine noise hits both alike.
  t=$("$cli" bench --scenario cross --agents "$agents" --steps "$steps" --quiet |
      python3 -c 'import json,sys; print(json.load(sys.stdin)["agent_steps_per_second"])')
  d=$("$peer_bin" --scenario circle --agents "$agents" --steps "$steps" |
      sed -n 's/.*agent_steps_per_s=\([0-9.e+]*\).*/\1/p')
  throng+=("$t") detour+=("$d")
done
python3 - "$agents" "$steps" "${throng[*]}" "${detour[*]}" <<'PY'
import json, statistics, sys
agents, steps = int(sys.argv[1]), int(sys.argv[2])
t = [float(x) for x in sys.argv[3].split()]
d = [float(x) for x in sys.argv[4].split()]
print(json.dumps({"bench": "cross_vs_detourcrowd", "agents": agents, "steps": steps, "runs": len(t),
                  "throng_agent_steps_per_second": statistics.median(t),
                  "detourcrowd_agent_steps_per_second": statistics.median(d),
                  "ratio": statistics.median(t) / statistics.median(d),
                  "throng_runs": t, "detourcrowd_runs": d}))
PY

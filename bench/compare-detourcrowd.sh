#!/usr/bin/env bash
# Runs DetourCrowd (../shared/peers, Debian's librecast-dev) and Throng on the same
# `cross` scenario in one go, several times, and prints one JSON object with the medians
# and the ratio; and the ratio without Throng's count phase (its overlap and density
# figures, which the peer works out outside its timing), from each run's phase times.
# Same agents, same goals: throng-bench-cross writes the layout
# (BenchScenarios.h: concentric rings, antipodal goals) and the peer, patched with
# bench/peers/detourcrowd-layout.patch (its --layout option), reads it.
# Usage: bench/compare-detourcrowd.sh [AGENTS] [STEPS] [RUNS]; THREADS=N in the environment
# sets Throng's thread count (default: one per core).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
agents="${1:-10000}" steps="${2:-240}" runs="${3:-3}"
peers="$root/../shared/peers"
cli="$root/build/app/cli/throng-cli"
cross="$root/build/bench/throng-bench-cross"
peer_dir="${TMPDIR:-/tmp}/throng-detourcrowd-peer"
peer_bin="$peer_dir/detourcrowd_bench"
layout="$peer_dir/cross-$agents.txt"

dpkg-query -W -f='${Status}' librecast-dev 2>/dev/null | grep -q "install ok installed" || {
  sudo=""; [ "$(id -u)" = 0 ] || sudo=sudo
  $sudo apt-get install -y -q librecast-dev >&2
}
if [ ! -x "$peer_bin" ] || [ "$root/bench/peers/detourcrowd-layout.patch" -nt "$peer_bin" ]; then
  mkdir -p "$peer_dir"
  cp "$peers/detourcrowd_bench.cpp" "$peers/Makefile" "$peer_dir/"
  chmod u+w "$peer_dir"/*
  patch -s -d "$peer_dir" -p0 < "$root/bench/peers/detourcrowd-layout.patch" >&2
  make -s -C "$peer_dir" OUT="$peer_bin" >&2
fi
[ -x "$cli" ] || "$root/scripts/build.sh" >&2
[ -x "$cross" ] || cmake --build "$root/build" --target throng-bench-cross >&2
"$cross" --write-layout "$layout" "$agents"

threads=(); [ -n "${THREADS:-}" ] && threads=(--threads "$THREADS")
throng=() uncounted=() detour=()
for ((r = 0; r < runs; ++r)); do
  # Alternate the two so machine noise hits both alike.
  # Each run's output is read only after it ends: a reader starting up beside a
  # half-second run on two cores takes one of them from it.
  out=$("$cli" bench --scenario cross --agents "$agents" --steps "$steps" "${threads[@]}" --quiet)
  t=$(python3 -c 'import json,sys; print(json.load(sys.stdin)["agent_steps_per_second"])' <<< "$out")
  # The same run less its count phase (phase_ms_per_step), which the peer does outside
  # its timing: the two measured with equal work in that respect.
  u=$(python3 -c 'import json,sys
o = json.load(sys.stdin)
print(o["agents"] * o["steps"] / (o["seconds"] - o["phase_ms_per_step"]["count"] * o["steps"] / 1000))' <<< "$out")
  out=$("$peer_bin" --layout "$layout" --steps "$steps")
  d=$(sed -n 's/.*agent_steps_per_s=\([0-9.e+]*\).*/\1/p' <<< "$out")
  throng+=("$t") uncounted+=("$u") detour+=("$d")
done
python3 - "$agents" "$steps" "${throng[*]}" "${detour[*]}" "${uncounted[*]}" <<'PY'
import json, statistics, sys
agents, steps = int(sys.argv[1]), int(sys.argv[2])
t = [float(x) for x in sys.argv[3].split()]
d = [float(x) for x in sys.argv[4].split()]
u = [float(x) for x in sys.argv[5].split()]
print(json.dumps({"bench": "cross_vs_detourcrowd", "agents": agents, "steps": steps, "runs": len(t),
                  "throng_agent_steps_per_second": statistics.median(t),
                  "detourcrowd_agent_steps_per_second": statistics.median(d),
                  "ratio": statistics.median(t) / statistics.median(d),
                  "throng_without_count_phase_agent_steps_per_second": statistics.median(u),
                  "ratio_without_count_phase": statistics.median(u) / statistics.median(d),
                  "throng_runs": t, "detourcrowd_runs": d, "throng_without_count_phase_runs": u}))
PY

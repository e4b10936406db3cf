#!/usr/bin/env bash
# Thread scaling on a quiet and on a busy machine: `throng-cli bench` (cross, 10,000
# agents by default) on 1 and on 2 threads, alternating, several times, first alone and
# then beside a busy loop pinned on the last core (another process on a render node, a
# browser on a laptop). Prints one JSON object with each case's median agent-steps/s and
# the 2-thread/1-thread ratio of the medians. No environment variable is set.
# Usage: bench/threads-under-load.sh [AGENTS] [STEPS] [RUNS] [SCENARIO]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
agents="${1:-10000}" steps="${2:-120}" runs="${3:-5}" scenario="${4:-cross}"
cli="${THRONG_CLI:-$root/build/app/cli/throng-cli}"
[ -x "$cli" ] || "$root/scripts/build.sh" >&2
last=$(( $(nproc) - 1 ))

rate() {  # threads -> agent-steps/s of one bench run
  "$cli" bench --scenario "$scenario" --agents "$agents" --steps "$steps" --threads "$1" 2>/dev/null |
    python3 -c 'import json, sys; print(json.load(sys.stdin)["agent_steps_per_second"])'
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

measure() {  # case name -> JSON fields
  local one=() two=()
  for ((r = 0; r < runs; ++r)); do
    one+=("$(rate 1)")
    two+=("$(rate 2)")
  done
  local m1 m2
  m1=$(median "${one[@]}") m2=$(median "${two[@]}")
  printf '"%s": {"one_thread": %s, "two_threads": %s, "two_over_one": %s, "runs_one": [%s], "runs_two": [%s]}' \
    "$1" "$m1" "$m2" "$(awk -v a="$m2" -v b="$m1" 'BEGIN {printf "%.3f", a / b}')" \
    "$(IFS=,; echo "${one[*]}")" "$(IFS=,; echo "${two[*]}")"
}

quiet=$(measure quiet)
taskset -c "$last" sh -c 'while :; do :; done' &
busy=$!
trap 'kill $busy 2>/dev/null || true' EXIT
loaded=$(measure one_core_busy)
kill "$busy"
printf '{"scenario": "%s", "agents": %s, "steps": %s, "cores": %s, %s, %s}\n' \
  "$scenario" "$agents" "$steps" "$(nproc)" "$quiet" "$loaded"

#!/usr/bin/env bash
# Installs what is missing, builds everything and runs every test: the GUI suites under
# xvfb-run, then the simcore, nav, traffic, brain and export suites again under
# AddressSanitizer and UndefinedBehaviorSanitizer (built while the first tests run). Exits
# non-zero on any failure.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/deps.sh" test
"$root/scripts/build.sh"
jobs="$(nproc)"

# The sanitizer build runs at the lowest priority while the Release tests run, and takes
# the processor time they leave idle without slowing them (a niced process gets a core
# only when no test wants it).
san="$root/build-sanitize"
source "$root/scripts/ccache.sh"
if [ ! -f "$san/build.ninja" ]; then
  # -O1 with line tables only: the sanitizers' usual setting; it builds in about half the
  # time of -O2 -g, which keeps the whole CI run well within its 30 minutes.
  cmake -S "$root" -B "$san" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTHRONG_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DTHRONG_BUILD_EDITOR=OFF "${ccache_args[@]}" >/dev/null
fi
san_log="$san/background-build.log"
# Ninja itself, not through cmake --build: on SIGTERM ninja stops the compilers it runs.
# In this script's session, so that nice ranks it below the tests (the kernel's autogroups
# share the processor equally between sessions, whatever their processes' nice values).
nice -n 19 ninja -C "$san" -j"$jobs" test_simcore test_worldbrain test_worldstate test_worldnav \
  test_nav test_traffic test_brain test_export test_sources test_layout >"$san_log" 2>&1 &
san_build=$!
# Whatever happens to the Release tests, the background build does not outlive this script.
trap 'kill "$san_build" 2>/dev/null || true' EXIT

echo "== all tests (Release; the sanitizer build runs beside them at low priority)"
xvfb-run -a -s "-screen 0 1920x1080x24" ctest --test-dir "$root/build" --output-on-failure -j"$jobs"

echo "== simcore, nav, traffic, brain and export under ASan + UBSan"
san_status=0
wait "$san_build" || san_status=$?
trap - EXIT
tail -n 3 "$san_log"
if [ "$san_status" -ne 0 ]; then
  cat "$san_log"
  echo "the sanitizer build failed (exit $san_status)" >&2
  exit "$san_status"
fi
# Left out here, to keep CI well within its 30 minutes (a cold run took 36 on 2 cores):
# - export.TestExternalReaders runs third-party readers (Blender, three.js, assimp) on our
#   files in their own processes, which the sanitizers do not watch; the export suite's
#   other classes write the same files under them.
# - The demos suite (whole demo scenes and golden hashes: 2 minutes here, besides its build)
#   and worldstate.TestThreadDeterminism (the same runs on 1 and 2 threads: 2 minutes) run
#   code the simcore, worldstate and worldnav suites run here too; what they add is checked
#   by the Release run above.
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir "$san" --output-on-failure -j"$jobs" -L '^(simcore|worldbrain|nav|traffic|brain|export)$' \
  -E '^(export\.TestExternalReaders|demos\..*|worldstate\.TestThreadDeterminism)$'

#!/usr/bin/env bash
# Installs what is missing, builds everything and runs every test: the GUI suites under
# xvfb-run, then the simcore, nav, traffic, brain and export suites again under
# AddressSanitizer and UndefinedBehaviorSanitizer. Exits non-zero on any failure.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/deps.sh" test
"$root/scripts/build.sh"
jobs="$(nproc)"
echo "== all tests (Release)"
xvfb-run -a -s "-screen 0 1920x1080x24" ctest --test-dir "$root/build" --output-on-failure -j"$jobs"

echo "== simcore, nav, traffic, brain and export under ASan + UBSan"
san="$root/build-sanitize"
source "$root/scripts/ccache.sh"
if [ ! -f "$san/build.ninja" ]; then
  # -O1 with line tables only: the sanitizers' usual setting; it builds in about half the
  # time of -O2 -g, which keeps the whole CI run well within its 30 minutes.
  cmake -S "$root" -B "$san" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTHRONG_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DTHRONG_BUILD_EDITOR=OFF "${ccache_args[@]}" >/dev/null
fi
cmake --build "$san" --target test_simcore test_worldbrain test_worldstate test_demos test_worldnav test_nav test_traffic test_brain test_export -- -j"$jobs"
# TestExternalReaders is left out here: it runs third-party readers (Blender, three.js,
# assimp) on our files in their own processes, which the sanitizers do not watch; the
# export suite's other classes write the same files under them.
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir "$san" --output-on-failure -j"$jobs" -L '^(simcore|worldbrain|nav|traffic|brain|export)$' \
  -E '^export\.TestExternalReaders$'

#!/usr/bin/env bash
# Builds test_thread_safety and only what it links with ThreadSanitizer (build-tsan/), then runs it: the library's
# const methods called from two threads on one object must give no data-race report. Not part of CI (a TSan build
# of the libraries takes long); run it after touching a class's buffers or its const methods.
# Usage: scripts/tsan.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$VISP_SSL_ROOT"

case "${1:-}" in
"") ;;
-h | --help)
  sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
  ;;
*)
  echo "tsan.sh: unknown argument '$1' (see --help)" >&2
  exit 2
  ;;
esac

build=build-tsan
log="$build/tsan.log"
mkdir -p "$build"
: >"$log"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
phase "configure ($build, -fsanitize=thread)"
# RelWithDebInfo: TSan's reports name source lines.
run_logged "$log" cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread \
  -DVISP_SSL_BUILD_TESTS=ON -DVISP_SSL_BUILD_TUTORIALS=OFF -DVISP_SSL_BUILD_BENCHMARKS=OFF \
  -DVISP_SSL_WITH_ROSBAG=OFF
phase "build test_thread_safety"
run_logged "$log" cmake --build "$build" -j"$JOBS" --target test_thread_safety
phase "run test_thread_safety"
# The views are rendered before the test's threads start; one OpenMP thread keeps libgomp's own synchronisation,
# which TSan cannot see, out of the report. halt_on_error: the first race fails the run.
OMP_NUM_THREADS=1 TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" "$build/test/test_thread_safety"
print_timings

#!/usr/bin/env bash
# Quick start, part 2: installs the Debian packages, builds everything in Release (build/) and runs every test
# with ctest; builds the API reference (doxygen); installs into install/ and builds the downstream example
# (example/consumer) against it, through pkg-config too, and from the build tree; then
# builds again with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/) and runs the tests there but the
# whole closed-loop missions (ctest label closed-loop);
# then builds the libFuzzer targets with clang and runs each on its corpus and for 10 s (scripts/fuzz.sh,
# FUZZ_SECONDS to change); last, checks that the C++ files are formatted (scripts/format.sh --check).
# Usage: scripts/test.sh [--no-sanitize]
#   --no-sanitize   skip the sanitizer build and the fuzzers (a quicker local run)
# Exits non-zero on the first failure; prints the time of each phase. Build logs: build*/build.log.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$VISP_SSL_ROOT"

sanitize=1
for arg in "$@"; do
  case "$arg" in
  --no-sanitize) sanitize=0 ;;
  -h | --help)
    sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
    exit 0
    ;;
  *)
    echo "test.sh: unknown option '$arg' (see --help)" >&2
    exit 2
    ;;
  esac
done
trap 'print_timings' EXIT

phase "install Debian packages"
bash scripts/setup-deps.sh

phase "configure and build, Release (build/)"
rm -f build/build.log
# Every option spelled out: a build/ tree left configured otherwise by hand must not skip anything.
run_logged build/build.log cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DVISP_SSL_SANITIZE=OFF \
  -DVISP_SSL_BUILD_TESTS=ON -DVISP_SSL_BUILD_TUTORIALS=ON -DVISP_SSL_BUILD_BENCHMARKS=ON
run_logged build/build.log cmake --build build -j"$JOBS"

phase "ctest, Release"
ctest --test-dir build --output-on-failure --no-tests=error -j"$JOBS"

phase "API reference (doxygen, a warning fails)"
run_logged build/build.log cmake --build build --target doc

phase "install into install/ and build example/consumer against it"
rm -rf install build-consumer build-consumer-tree
run_logged build/build.log cmake --install build --prefix "$VISP_SSL_ROOT/install"
run_logged build-consumer/build.log cmake -S example/consumer -B build-consumer -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$VISP_SSL_ROOT/install"
run_logged build-consumer/build.log cmake --build build-consumer -j"$JOBS"
build-consumer/ssl-consumer
# The same program through pkg-config (visp_ssl.pc), and the CMake package from the build tree.
pc_dir=$(dirname "$(find install -name visp_ssl.pc | head -n 1)")
# shellcheck disable=SC2046  # pkg-config's flags are meant to split
run_logged build-consumer/build.log c++ example/consumer/main.cpp -o build-consumer/ssl-consumer-pkgconfig \
  $(PKG_CONFIG_PATH="$VISP_SSL_ROOT/$pc_dir" pkg-config --cflags --libs visp_ssl)
build-consumer/ssl-consumer-pkgconfig
run_logged build-consumer/build.log cmake -S example/consumer -B build-consumer-tree \
  -DCMAKE_BUILD_TYPE=Release -DVISP_SSL_DIR="$VISP_SSL_ROOT/build"
run_logged build-consumer/build.log cmake --build build-consumer-tree -j"$JOBS"
build-consumer-tree/ssl-consumer
# An installed tutorial reads the installed data (share/visp_ssl), not the source tree's.
env -u DISPLAY VISP_SSL_DATA_DIR='' install/bin/tutorial-ssl-detector-pose --output build-consumer/detector-pose \
  > build-consumer/detector-pose.txt 2>&1
grep -q "^Input: .*/install/share/visp_ssl/images/" build-consumer/detector-pose.txt ||
  { echo "test.sh: the installed tutorial-ssl-detector-pose does not read the installed data" >&2; exit 1; }

if [ "$sanitize" -eq 1 ]; then
  phase "configure and build, ASan+UBSan (build-asan/)"
  rm -f build-asan/build.log
  # Line tables (-g1) are all a sanitizer report needs to name each frame's function, file and line; full debug
  # information makes each object more than twice as large and its compilation a quarter to a third slower. -O1, as
  # the sanitizers' documentation advises: on 2 cores it builds in 4 min 9 s against 5 min 46 s at -O2 and runs the
  # tests in 4 min 31 s against 4 min 3 s (2026-12-06, commit 938e081).
  run_logged build-asan/build.log cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVISP_SSL_SANITIZE=ON \
    -DVISP_SSL_BUILD_TESTS=ON -DVISP_SSL_BUILD_TUTORIALS=ON -DVISP_SSL_BUILD_BENCHMARKS=OFF \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
  run_logged build-asan/build.log cmake --build build-asan -j"$JOBS"

  phase "ctest, ASan+UBSan"
  # Leaks count as failures: ViSP, OpenCV and OpenMP report none, so nothing needs suppressing. Should a
  # third-party leak appear, list it in an LSan suppression file (LSAN_OPTIONS=suppressions=...) rather than
  # turning leak detection off.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
  # The whole closed-loop missions (label closed-loop, test/CMakeLists.txt) ran in the Release phase; under the
  # sanitizers they would add minutes of code that the shorter e2e runs and the unit tests sanitize already.
  ctest --test-dir build-asan --output-on-failure --no-tests=error -j"$JOBS" -LE closed-loop
fi

if [ "$sanitize" -eq 1 ]; then
  phase "fuzz targets: build with clang, committed corpora, ${FUZZ_SECONDS:-10} s each (scripts/fuzz.sh)"
  # Nine targets of 10 s each and their corpora, two at a time on 2 cores, after the clang build of the library and
  # the bag reader: the stage took 2 min 33 s of a clean-clone run on a 2-core VM (2026-12-06, commit 44391cd).
  bash scripts/fuzz.sh --time "${FUZZ_SECONDS:-10}"
fi

# Last, so that a formatting slip does not hide the test results.
phase "check formatting (scripts/format.sh --check)"
bash scripts/format.sh --check

echo "test.sh: all checks passed"

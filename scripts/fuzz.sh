#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang 14 (ASan, UBSan, float-cast-overflow; build-fuzz/), runs each on
# its committed corpus (fuzz/corpus/<target>/) as a regression, then fuzzes each for SECONDS from a copy of that
# corpus (the committed one is never modified; new inputs and crashes stay in build-fuzz/runs/<target>/).
# Usage: scripts/fuzz.sh [--time SECONDS] [--regression-only] [--runs N] [TARGET ...]
#   --time SECONDS     fuzzing time per target (default 10)
#   --runs N           instead of a time, stop each target after N executions (a long campaign: see doc/fuzzing.md)
#   --regression-only  only run the committed corpora
#   TARGET             fuzz_target_file, fuzz_camera_file, ... (default: all those built)
# Runs as many targets at a time as there are cores. Exits non-zero if a target crashed, leaked, had a sanitizer
# report or a timeout (the first such in the targets' order); the reproducer is in build-fuzz/runs/.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$VISP_SSL_ROOT"

seconds=10
runs=""
regressionOnly=0
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
  --time) seconds="$2"; shift ;;
  --runs) runs="$2"; shift ;;
  --regression-only) regressionOnly=1 ;;
  -h | --help)
    sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
    exit 0
    ;;
  fuzz_*) targets+=("$1") ;;
  *)
    echo "fuzz.sh: unknown argument '$1' (see --help)" >&2
    exit 2
    ;;
  esac
  shift
done

dict_of() {
  case "$1" in
  fuzz_target_file) echo fuzz/dict/target_file.dict ;;
  fuzz_camera_file) echo fuzz/dict/camera_file.dict ;;
  fuzz_sequence_json) echo fuzz/dict/sequence_json.dict ;;
  fuzz_frames_csv | fuzz_sequence_folder) echo fuzz/dict/frames_csv.dict ;;
  fuzz_odometry_csv) echo fuzz/dict/odometry_csv.dict ;;
  fuzz_rosbag) echo fuzz/dict/rosbag.dict ;;
  fuzz_detector) echo fuzz/dict/image.dict ;;
  *) echo "" ;;
  esac
}

build=build-fuzz
rm -f "$build/build.log"
# Line tables (-g1) are all a finding's stack trace needs to name files and lines (scripts/test.sh says why not -g).
run_logged "$build/build.log" cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 \
  -DCMAKE_CXX_COMPILER=clang++-14 -DVISP_SSL_BUILD_FUZZERS=ON -DVISP_SSL_SANITIZE=OFF -DVISP_SSL_BUILD_TESTS=OFF \
  -DVISP_SSL_BUILD_TUTORIALS=OFF -DVISP_SSL_BUILD_BENCHMARKS=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG"
# The targets this configuration builds (fuzz_rosbag only with the ROS packages): fuzz/CMakeLists.txt lists them.
mapfile -t built <"$build/fuzz/targets.txt"
if [ ${#targets[@]} -eq 0 ]; then
  targets=("${built[@]}")
fi
for t in "${targets[@]}"; do
  if ! printf '%s\n' "${built[@]}" | grep -qx -- "$t"; then
    echo "fuzz.sh: $t is not built here (targets: ${built[*]}; fuzz_rosbag needs Debian's ROS packages)" >&2
    exit 2
  fi
done
run_logged "$build/build.log" cmake --build "$build" -j"$JOBS" --target "${targets[@]}"

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# One target: its committed corpus as a regression, then (unless --regression-only) the fuzzing. Its report goes
# to stdout and stderr; the exit status says whether it passed.
fuzz_one() {
  local t=$1 bin="$build/fuzz/$1" work="$build/runs/$1" start dict execs limit
  rm -rf "$work"
  mkdir -p "$work/corpus" || return 1
  # Regression: every committed input once.
  start=$SECONDS
  "$bin" -runs=0 "fuzz/corpus/$t" >"$work/regression.log" 2>&1 || {
    tail -n 40 "$work/regression.log" >&2
    echo "fuzz.sh: $t: the committed corpus fails (log: $work/regression.log)" >&2
    return 1
  }
  echo "fuzz.sh: $t: corpus of $(ls "fuzz/corpus/$t" | wc -l) inputs passes ($((SECONDS - start)) s)"
  [ "$regressionOnly" -eq 1 ] && return 0
  cp "fuzz/corpus/$t"/* "$work/corpus/" || return 1
  dict=$(dict_of "$t")
  limit=(-max_total_time="$seconds")
  [ -n "$runs" ] && limit=(-runs="$runs")
  start=$SECONDS
  # A fixed seed: the same inputs in every run of the same tree, so that CI does not turn red by chance.
  (cd "$work" && "$OLDPWD/$bin" "${limit[@]}" ${dict:+-dict="$OLDPWD/$dict"} -seed=1 -rss_limit_mb=2048 -timeout=20 \
    -max_len=65536 -print_final_stats=1 corpus >fuzz.log 2>&1) || {
    tail -n 60 "$work/fuzz.log" >&2
    echo "fuzz.sh: $t: finding (log and reproducer in $work)" >&2
    return 1
  }
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/fuzz.log" | grep -o '[0-9]*$' || echo "?")
  echo "fuzz.sh: $t: no finding in $((SECONDS - start)) s, $execs executions"
}

# Each target is one process on one core: JOBS of them run at a time. Their reports are printed in the targets'
# order once all have finished; the first that failed sets the exit status.
mkdir -p "$build/runs"
for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do sleep 0.2; done
  (
    set +e
    fuzz_one "$t" >"$build/runs/$t.report" 2>&1
    echo $? >"$build/runs/$t.status"
  ) &
done
wait
for t in "${targets[@]}"; do
  cat "$build/runs/$t.report"
  if [ "$(cat "$build/runs/$t.status")" != 0 ]; then
    echo "fuzz.sh: $t failed (report: $build/runs/$t.report)" >&2
    exit 1
  fi
done

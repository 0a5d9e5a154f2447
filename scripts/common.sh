# Helpers shared by the scripts in this folder (sourced, not run).

# Repository root, whatever the caller's working directory.
VISP_SSL_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
JOBS="$(nproc 2>/dev/null || echo 2)"

# run_logged LOG CMD...: runs CMD with its output appended to LOG; on failure shows the log's tail,
# so that a CI page shows the compiler error without scrolling through a whole build.
run_logged() {
  local log="$1"
  shift
  mkdir -p "$(dirname "$log")"
  echo "\$ $*" >>"$log"
  if ! "$@" >>"$log" 2>&1; then
    echo "FAILED: $* (last 40 lines of $log below)" >&2
    tail -n 40 "$log" >&2
    return 1
  fi
}

# phase NAME: prints the time spent in the previous phase and starts a new one.
PHASE_NAME=""
PHASE_START=0
PHASE_SUMMARY=()
phase() {
  phase_end
  PHASE_NAME="$1"
  PHASE_START=$SECONDS
  echo "== $PHASE_NAME"
}
phase_end() {
  if [ -n "$PHASE_NAME" ]; then
    local t=$((SECONDS - PHASE_START))
    PHASE_SUMMARY+=("$(printf '%4d:%02d  %s' $((t / 60)) $((t % 60)) "$PHASE_NAME")")
    PHASE_NAME=""
  fi
}
# print_timings: the per-phase table, then the total.
print_timings() {
  phase_end
  echo "== timings (min:sec)"
  printf '%s\n' "${PHASE_SUMMARY[@]}"
  printf '%4d:%02d  total\n' $((SECONDS / 60)) $((SECONDS % 60))
}

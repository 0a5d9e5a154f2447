#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-servo-monte-carlo: --help lists every option, bad options exit 2 with one line on
# stderr, and a short run (2 runs, perfect sensor, no rendering) writes runs.csv and summary.md; 1 and 2 threads
# give the same files.
# Usage: servo_monte_carlo.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
E2E_FAIL_FAST=1
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-servo-monte-carlo "$@"

"$BIN" --help > "$WORK/help" || fail "--help exit code"
for opt in --runs --seed --methods --time-limit --max-current --threads --traces --output-dir --width --height \
           --small --quiet --help ssl apriltag truth runs.csv summary.md; do
  grep -q -- "$opt" "$WORK/help" || fail "--help does not mention $opt"
done

check_error() { # pattern args...
  local pattern=$1; shift
  "$BIN" "$@" > "$WORK/out" 2> "$WORK/err"
  local rc=$?
  [ $rc -eq 2 ] || fail "$* : exit code $rc, expected 2"
  [ "$(wc -l < "$WORK/err")" -eq 1 ] || fail "$* : expected one line on stderr, got: $(cat "$WORK/err")"
  grep -q -- "$pattern" "$WORK/err" || fail "$* : stderr does not mention $pattern: $(cat "$WORK/err")"
}
check_error "unknown option" --bogus
check_error "--runs" --runs 0
check_error "--methods" --methods ssl,sift
check_error "--time-limit" --time-limit -1
check_error "needs a value" --seed

# A perfect sensor needs no image: 2 runs of 30 s simulated take well under a second.
for threads in 1 2; do
  out="$WORK/out-$threads"
  "$BIN" --runs 2 --methods truth --time-limit 30 --threads $threads --quiet --traces --output-dir "$out" \
    > "$WORK/log-$threads" 2> "$WORK/err" || fail "run exit code $? with $threads thread(s): $(cat "$WORK/err")"
  [ ! -s "$WORK/err" ] || fail "--quiet run wrote on stderr: $(cat "$WORK/err")"
  csv="$out/runs.csv"
  [ -f "$csv" ] || fail "runs.csv missing"
  head -1 "$csv" | grep -q "^run,method,water,seed,start_distance,lateral,heading_deg,depth_offset,current_speed,current_dir_deg,stand_off,start_range,docked,time_to_dock,standoff_rms,settled_steps,first_detection,collisions_outside_dock,lost_events,final_state,sim_time$" \
    || fail "runs.csv header: $(head -1 "$csv")"
  [ "$(($(wc -l < "$csv") - 1))" -eq 2 ] || fail "expected 2 rows in runs.csv, got $(($(wc -l < "$csv") - 1))"
  for run in 0 1; do
    grep -q "^$run,truth,\(clear\|coastal\),[0-9]*,[0-9.]*,-\?[0-9.]*," "$csv" || fail "no row for run $run: $(cat "$csv")"
    [ -s "$out/run-$run-truth.csv" ] || fail "--traces: run-$run-truth.csv missing"
  done
  awk -F, 'NR > 1 && ($13 != 0 && $13 != 1) { exit 1 }' "$csv" || fail "docked column is not 0/1: $(cat "$csv")"
  [ -s "$out/summary.md" ] || fail "summary.md missing"
  grep -q "^| truth | all | [0-2]/2 | " "$out/summary.md" || fail "summary.md: no 'truth | all' row: $(cat "$out/summary.md")"
  grep -q "^| truth | all | " "$WORK/log-$threads" || fail "summary not on stdout"
done
cmp -s "$WORK/out-1/runs.csv" "$WORK/out-2/runs.csv" || fail "runs.csv differs between 1 and 2 threads"
cmp -s "$WORK/out-1/summary.md" "$WORK/out-2/summary.md" || fail "summary.md differs between 1 and 2 threads"
e2e_finish

#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-servo-monte-carlo: --help lists every option, bad options exit 2 with one line on
# stderr, a short run (2 runs, perfect sensor, no rendering) writes runs.csv, summary.md and outcomes.png, 1 and 2
# threads give the same files, and SSL and AprilTag find the target on a short rendered run. Whether the mission
# docks is servo_monte_carlo_mission.sh's check.
# Usage: servo_monte_carlo.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
E2E_FAIL_FAST=1
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-servo-monte-carlo "$@"

"$BIN" --help > "$WORK/help" || fail "--help exit code"
for opt in --runs --seed --methods --time-limit --rate --max-current --threads --traces --output-dir --width --height \
           --small --quiet --help --start-range --start-heading --water --station-keeping --dock-in-transit --no-station-keeping --no-dock-in-transit ssl apriltag truth ssl-raw apriltag-raw \
           runs.csv summary.md outcomes.png never-found lost hold-not-reached missed-board collision time-out; do
  grep -q -- "$opt" "$WORK/help" || fail "--help does not mention $opt"
done

expect_error 2 "unknown option" --bogus
expect_error 2 "--runs" --runs 0
expect_error 2 "--methods" --methods ssl,sift
expect_error 2 "--time-limit" --time-limit -1
expect_error 2 "--rate" --rate 0
expect_error 2 "--rate" --rate 25
expect_error 2 "needs a value" --seed
expect_error 2 "--start-range" --start-range 3,2
expect_error 2 "empty folder" --output-dir ""

# Without --output-dir the files go to monte-carlo-out/, not into the working directory.
(cd "$WORK" && "$BIN" --runs 1 --methods truth --time-limit 5 --quiet > log-default 2>&1) || fail "default output: exit code"
[ -s "$WORK/monte-carlo-out/runs.csv" ] && [ ! -e "$WORK/runs.csv" ] && pass "default output folder monte-carlo-out" ||
  fail "default output: $(ls "$WORK")"
expect_error 2 "--start-range" --start-range 2
expect_error 2 "--start-heading" --start-heading 181
expect_error 2 "--water" --water turbid

# A perfect sensor needs no image: 2 runs of 30 s simulated take well under a second.
for threads in 1 2; do
  out="$WORK/out-$threads"
  "$BIN" --runs 2 --methods truth --time-limit 30 --threads $threads --quiet --traces --output-dir "$out" \
    > "$WORK/log-$threads" 2> "$WORK/err" || fail "run exit code $? with $threads thread(s): $(cat "$WORK/err")"
  [ ! -s "$WORK/err" ] || fail "--quiet run wrote on stderr: $(cat "$WORK/err")"
  csv="$out/runs.csv"
  [ -f "$csv" ] || fail "runs.csv missing"
  head -1 "$csv" | grep -q "^run,method,water,seed,start_distance,lateral,heading_deg,depth_offset,current_speed,current_dir_deg,stand_off,start_range,docked,time_to_dock,standoff_rms,settled_steps,first_detection,collisions_outside_dock,lost_events,final_state,sim_time,start_in_view,failure$" \
    || fail "runs.csv header: $(head -1 "$csv")"
  [ "$(($(wc -l < "$csv") - 1))" -eq 2 ] || fail "expected 2 rows in runs.csv, got $(($(wc -l < "$csv") - 1))"
  for run in 0 1; do
    grep -q "^$run,truth,\(clear\|coastal\),[0-9]*,[0-9.]*,-\?[0-9.]*," "$csv" || fail "no row for run $run: $(cat "$csv")"
    [ -s "$out/run-$run-truth.csv" ] || fail "--traces: run-$run-truth.csv missing"
  done
  awk -F, 'NR > 1 && ($13 != 0 && $13 != 1) { exit 1 }' "$csv" || fail "docked column is not 0/1: $(cat "$csv")"
  # Every run starts with the target out of view; a run docks or names its failure.
  awk -F, 'NR > 1 && $22 != 0 { exit 1 }' "$csv" || fail "a start with the target in view: $(cat "$csv")"
  awk -F, 'NR > 1 && (($13 == 1) != ($23 == "")) { exit 1 }' "$csv" || fail "failure column: $(cat "$csv")"
  [ -s "$out/outcomes.png" ] || fail "outcomes.png missing"
  [ -s "$out/summary.md" ] || fail "summary.md missing"
  grep -q "^| truth | all | [0-2]/2 | " "$out/summary.md" || fail "summary.md: no 'truth | all' row: $(cat "$out/summary.md")"
  grep -q "^| truth | all | " "$WORK/log-$threads" || fail "summary not on stdout"
done
cmp -s "$WORK/out-1/runs.csv" "$WORK/out-2/runs.csv" || fail "runs.csv differs between 1 and 2 threads"
cmp -s "$WORK/out-1/summary.md" "$WORK/out-2/summary.md" || fail "summary.md differs between 1 and 2 threads"
# Station keeping and docking in transit are the defaults; the summary says which behaviour ran.
grep -q "station keeping on the odometry, docking in transit across a current" "$WORK/out-1/summary.md" ||
  fail "summary.md does not say the default behaviour: $(head -1 "$WORK/out-1/summary.md")"
"$BIN" --runs 1 --methods truth --time-limit 5 --no-station-keeping --no-dock-in-transit --quiet \
  --output-dir "$WORK/no-odometry" > /dev/null 2> "$WORK/err" || fail "--no-station-keeping run: $(cat "$WORK/err")"
grep -q "no station keeping, no docking in transit" "$WORK/no-odometry/summary.md" ||
  fail "summary.md does not say --no-station-keeping --no-dock-in-transit: $(head -1 "$WORK/no-odometry/summary.md")"
# --rate sets the control and camera period: at 2.5 Hz the steps of a trace are 0.4 s apart, and the summary says so.
"$BIN" --runs 1 --methods truth --time-limit 5 --rate 2.5 --traces --quiet --output-dir "$WORK/rate" > /dev/null \
  2> "$WORK/err" || fail "--rate 2.5 run: $(cat "$WORK/err")"
grep -q ", 2.50 Hz," "$WORK/rate/summary.md" || fail "summary.md does not say 2.50 Hz: $(head -1 "$WORK/rate/summary.md")"
awk -F, 'NR == 2 { t0 = $1 } NR == 3 { t1 = $1 } END { d = t1 - t0; exit !(d > 0.3999 && d < 0.4001) }' \
  "$WORK/rate/run-0-truth.csv" || fail "--rate 2.5: steps not 0.4 s apart: $(head -3 "$WORK/rate/run-0-truth.csv")"
grep -q ", 5.00 Hz," "$WORK/out-1/summary.md" || fail "summary.md does not say the default 5 Hz"
# The default water is mixed: the summary says that coastal starts stop at the visibility (4 m).
grep -q "start range 2.0-8.0 m (coastal starts capped at the visibility, 4.0 m)," "$WORK/out-1/summary.md" ||
  fail "summary.md does not say the coastal cap: $(head -1 "$WORK/out-1/summary.md")"
# The rendered methods on a 5 s run (320x240, the target out of view at the start): one row each, and each finds
# the target by searching (measured: first detection at 1.0 s for SSL, 1.4 s for AprilTag). Whether they dock is
# servo_monte_carlo_mission.sh's check.
out="$WORK/rendered"
"$BIN" --runs 1 --seed 3 --methods ssl,apriltag --small --start-range 2,2.5 --water clear --max-current 0 \
  --time-limit 5 --threads 2 --quiet --output-dir "$out" > /dev/null 2> "$WORK/err" \
  || fail "rendered run exit code $?: $(cat "$WORK/err")"
for method in ssl apriltag; do
  grep -q "^0,$method,clear," "$out/runs.csv" || fail "no $method row: $(cat "$out/runs.csv")"
done
awk -F, 'NR > 1 && $17 + 0 <= 0 { exit 1 }' "$out/runs.csv" || fail "a method did not find the target: $(cat "$out/runs.csv")"
e2e_finish

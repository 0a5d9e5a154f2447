#!/usr/bin/env bash
# End-to-end check of the missions of tutorial-ssl-servo-monte-carlo: a short fixed-seed mission (search from a
# start with the target out of view, align, home, dock) docks every run with SSL, AprilTag (fused) and the perfect
# sensor; across a current, docking in transit docks every run and station keeping alone does not.
# Usage: servo_monte_carlo_mission.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
E2E_FAIL_FAST=1
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-servo-monte-carlo "$@"

# The whole mission on a short fixed-seed run (320x240, clear still water, starts 2-2.5 m with the target out of
# view, the default behaviour): each method must find the target by searching and dock in both runs (measured: 2/2
# each).
out="$WORK/mission"
"$BIN" --runs 2 --seed 3 --methods ssl,apriltag,truth --small --start-range 2,2.5 --water clear --max-current 0 \
  --time-limit 90 --threads 2 --quiet --output-dir "$out" > "$WORK/log-mission" 2> "$WORK/err" \
  || fail "mission run exit code $?: $(cat "$WORK/err")"
for method in ssl apriltag truth; do
  grep -q "^| $method | all | 2/2 | " "$out/summary.md" || fail "$method did not dock 2/2: $(cat "$out/summary.md")"
done
awk -F, 'NR > 1 && $17 + 0 <= 0 { exit 1 }' "$out/runs.csv" || fail "a target seen at the start: $(cat "$out/runs.csv")"
# Docking in transit with the perfect sensor, currents to 0.2 m/s: 4/4 docked (3/4 with station keeping alone,
# one run never holding the stand-off: measured).
out="$WORK/transit"
"$BIN" --runs 4 --methods truth --max-current 0.2 --time-limit 120 --threads 2 \
  --quiet --output-dir "$out" > "$WORK/log-transit" 2> "$WORK/err" || fail "transit run exit code $?: $(cat "$WORK/err")"
grep -q "docking in transit across a current" "$out/summary.md" || fail "summary.md does not say docking in transit"
grep -q "^| truth | all | 4/4 | " "$out/summary.md" || fail "transit: truth did not dock 4/4: $(cat "$out/summary.md")"
out="$WORK/no-transit"
"$BIN" --runs 4 --methods truth --max-current 0.2 --no-dock-in-transit --time-limit 120 --threads 2 \
  --quiet --output-dir "$out" > /dev/null 2> "$WORK/err" || fail "no-transit run exit code $?: $(cat "$WORK/err")"
grep -q "^| truth | all | 3/4 | " "$out/summary.md" || fail "station keeping alone: expected 3/4: $(cat "$out/summary.md")"
e2e_finish

#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-servo: --help lists every option, bad options exit 2 with one line on stderr,
# and short closed-loop runs (SSL and AprilTag, 320x240) write the CSV and the PNG.
# Usage: servo.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
E2E_FAIL_FAST=1
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-servo "$@"

"$BIN" --help > "$WORK/help" || fail "--help exit code"
for opt in --scenario --method --duration --seed --output-dir --width --height --small --supersampling --quiet \
           --help fig7 fig8 fig9 field ssl apriltag truth; do
  grep -q -- "$opt" "$WORK/help" || fail "--help does not mention $opt"
done

expect_error 2 "unknown option" --bogus
expect_error 2 "--scenario" --scenario fig10
expect_error 2 "--method" --method sift
expect_error 2 "--duration" --duration -3
expect_error 2 "--duration" --duration abc
expect_error 2 "needs a value" --seed
expect_error 2 "--supersampling" --supersampling 0
expect_error 2 "empty folder" --output-dir ""

# Without --output-dir the files go to servo-out/, not into the working directory.
(cd "$WORK" && "$BIN" --scenario fig9 --small --duration 1 --quiet > log-default 2>&1) || fail "default output: exit code"
[ -s "$WORK/servo-out/servo-fig9-ssl.csv" ] && [ ! -e "$WORK/servo-fig9-ssl.csv" ] && pass "default output folder servo-out" ||
  fail "default output: $(ls "$WORK")"

for method in ssl apriltag; do
  "$BIN" --scenario fig9 --small --duration 20 --method $method --quiet --output-dir "$WORK/out-$method" \
    > "$WORK/log" 2> "$WORK/err" || fail "$method run exit code $?: $(cat "$WORK/err")"
  csv="$WORK/out-$method/servo-fig9-$method.csv"
  [ -s "$WORK/out-$method/servo-fig9-$method.png" ] || fail "$method: PNG missing"
  [ -f "$csv" ] || fail "$method: CSV missing"
  head -1 "$csv" | grep -q "^t,state,nb_points,est_range,true_range,yaw_rate_demand,yaw_rate,heading_deg,depth," \
    || fail "$method: CSV header: $(head -1 "$csv")"
  rows=$(($(wc -l < "$csv") - 1))
  [ "$rows" -ge 90 ] && [ "$rows" -le 102 ] || fail "$method: expected about 100 rows (20 s at 5 Hz), got $rows"
  grep -q "final state" "$WORK/log" || fail "$method: no summary line: $(cat "$WORK/log")"
done
e2e_finish

#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-servo: --help lists every option, bad options exit 2 with one line on stderr,
# and short closed-loop runs (SSL and AprilTag, 320x240) write the CSV and the PNG.
# Usage: servo.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
set -u
bin="$1/tutorial-ssl-servo"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$bin" --help > "$work/help" || fail "--help exit code"
for opt in --scenario --method --duration --seed --output-dir --width --height --small --supersampling --quiet \
           --help fig7 fig8 fig9 field ssl apriltag truth; do
  grep -q -- "$opt" "$work/help" || fail "--help does not mention $opt"
done

check_error() { # pattern args...
  local pattern=$1; shift
  "$bin" "$@" > "$work/out" 2> "$work/err"
  local rc=$?
  [ $rc -eq 2 ] || fail "$* : exit code $rc, expected 2"
  [ "$(wc -l < "$work/err")" -eq 1 ] || fail "$* : expected one line on stderr, got: $(cat "$work/err")"
  grep -q -- "$pattern" "$work/err" || fail "$* : stderr does not mention $pattern: $(cat "$work/err")"
}
check_error "unknown option" --bogus
check_error "--scenario" --scenario fig10
check_error "--method" --method sift
check_error "--duration" --duration -3
check_error "--duration" --duration abc
check_error "needs a value" --seed
check_error "--supersampling" --supersampling 0

for method in ssl apriltag; do
  "$bin" --scenario fig9 --small --duration 20 --method $method --quiet --output-dir "$work/out-$method" \
    > "$work/log" 2> "$work/err" || fail "$method run exit code $?: $(cat "$work/err")"
  csv="$work/out-$method/servo-fig9-$method.csv"
  [ -s "$work/out-$method/servo-fig9-$method.png" ] || fail "$method: PNG missing"
  [ -f "$csv" ] || fail "$method: CSV missing"
  head -1 "$csv" | grep -q "^t,state,nb_points,est_range,true_range,yaw_rate_demand,yaw_rate,heading_deg,depth," \
    || fail "$method: CSV header: $(head -1 "$csv")"
  rows=$(($(wc -l < "$csv") - 1))
  [ "$rows" -ge 90 ] && [ "$rows" -le 102 ] || fail "$method: expected about 100 rows (20 s at 5 Hz), got $rows"
  grep -q "final state" "$work/log" || fail "$method: no summary line: $(cat "$work/log")"
done
echo "servo.sh: OK"

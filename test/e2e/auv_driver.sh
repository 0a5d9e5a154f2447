#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-auv-driver: the driver skeleton vpSSLRobotAuvTemplate, a vpRobot driven by
# vpSSLHomingBehaviour through setVelocity(ARTICULAR_FRAME), goes from SEARCH to HOME and holds the 2 m stand-off
# within 5 cm (true range; the tracker's range within 8 cm, its noise at 320x240) after 150 steps of 0.2 s, from 4 m;
# --help and bad options.
# Usage: auv_driver.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-auv-driver "$@"

"$BIN" --help > help || fail "--help exit code"
for opt in --steps --stand-off --help vpSSLRobotAuvTemplate ARTICULAR_FRAME; do
  grep -q -- "$opt" help || fail "--help does not mention $opt"
done
for args in "--bogus" "--steps 0" "--stand-off 5" "--stand-off abc" "--steps"; do
  # shellcheck disable=SC2086
  "$BIN" $args > out 2> err
  rc=$?
  [ $rc -eq 2 ] || fail "$args: exit code $rc, expected 2"
  [ "$(wc -l < err)" -eq 1 ] || fail "$args: expected one line on stderr, got: $(cat err)"
done

"$BIN" --steps 150 > log 2> err || fail "run: exit code $?: $(cat err)"
cat log
grep -q "state home" log || fail "never reached HOME"
final=$(grep "^final:" log)
echo "$final" | grep -q "final: state home after 150 steps" || fail "final line: $final"
read -r measured truth < <(echo "$final" | sed -n 's/.*measured range \([0-9.]*\) m, true range \([0-9.]*\) m.*/\1 \2/p')
[ -n "$measured" ] || fail "no ranges on the final line: $final"
awk -v m="$measured" -v t="$truth" 'BEGIN { exit !(m > 1.92 && m < 2.08 && t > 1.95 && t < 2.05) }' ||
  fail "range measured $measured m, true $truth m: not within 8 cm (measured) and 5 cm (true) of the 2 m stand-off"
e2e_finish

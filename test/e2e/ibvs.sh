#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-ibvs: ViSP's vpSimulatorCamera servoed onto the rendered ssl3-a3 target through
# the SSL tracker and vpSSLServoLaw converges (exit 0) within 300 iterations (12 s) at 320x240, and the pose it
# reaches is the desired one within 40 mm of range, 10 mm across and 5 deg (true errors, the tracker's accuracy at
# 1 m); --help, bad options (exit 2, one line), a run too short to converge (exit 1), --display without X (PNGs).
# Usage: ibvs.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-ibvs "$@"

"$BIN" --help > help || fail "--help exit code"
for opt in --stand-off --start --iterations --error --small --seed --display --output-dir --save-every --help; do
  grep -q -- "$opt" help || fail "--help does not mention $opt"
done

expect_error 2 "unknown option" --bogus
expect_error 2 "--stand-off" --stand-off 0.1
expect_error 2 "--start" --start 1,2,3
expect_error 2 "--start" --start 0,0,-1,0,0,0
expect_error 2 "--start" --start 0,0,1,0,0,x
expect_error 2 "--iterations" --iterations 0
expect_error 2 "--error" --error 0
expect_error 2 "needs a value" --output-dir

"$BIN" --small --iterations 300 > log 2> err
rc=$?
final=$(grep "^final:" log)
[ $rc -eq 0 ] || fail "run: exit code $rc: $(cat err) $final"
echo "$final"
echo "$final" | grep -q "final: converged" || fail "did not converge: $final"
read -r range lateral rotation < <(echo "$final" |
  sed -n 's/.*range error \(-\?[0-9.]*\) mm, lateral error \([0-9.]*\) mm, rotation error \([0-9.]*\) deg.*/\1 \2 \3/p')
[ -n "$range" ] || fail "no errors on the final line: $final"
awk -v r="$range" 'BEGIN { exit !(r > -40 && r < 40) }' || fail "range error $range mm not within 40 mm"
awk -v l="$lateral" 'BEGIN { exit !(l < 10) }' || fail "lateral error $lateral mm not below 10 mm"
awk -v a="$rotation" 'BEGIN { exit !(a < 5) }' || fail "rotation error $rotation deg not below 5 deg"
[ "$(grep -c "^iteration" log)" -ge 2 ] || fail "no progress lines"

# Too short to converge: exit 1 and one line saying so.
"$BIN" --small --iterations 5 > log 2> err
rc=$?
[ $rc -eq 1 ] || fail "5 iterations: exit code $rc, expected 1"
grep -q "did not fall below" err || fail "5 iterations: stderr: $(cat err)"
grep -q "^final: not converged" log || fail "5 iterations: final line: $(cat log)"

# --display without an X server: a notice, then the annotated images in ssl-ibvs/.
env -u DISPLAY "$BIN" --small --iterations 3 --display --save-every 2 > log 2> err
grep -q "no X display" err || fail "--display without X: no notice: $(cat err)"
[ -f ssl-ibvs/000000.png ] && [ -f ssl-ibvs/000002.png ] || fail "--display without X: images missing: $(ls ssl-ibvs)"
e2e_finish

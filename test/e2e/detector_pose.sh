#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-detector-pose, the port of ViSP's tutorial-apriltag-detector: without an X
# display it writes its two drawings, prints the target's pose on a sample image, and bad input is one line with
# the documented exit status.
# Usage: detector_pose.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-detector-pose "$@"
unset DISPLAY

"$BIN" --help > help || fail "--help exit code"
for opt in --input --intrinsic --camera_name --target --window --small_landmarks --nthreads --display_tag --color \
           --thickness --output --help; do
  grep -q -- "$opt" help || fail "--help does not mention $opt"
done

# The default input is the sample image of data/, seen by the camera of data/camera/camera-640x480.xml.
VISP_SSL_DATA_DIR="$DATA" "$BIN" --display_tag --output out > out.txt 2> out.err || fail "exit code $? $(cat out.err)"
grep -q "no X display" out.err || fail "no notice of the file fallback"
[ -s out/detections.png ] && [ -s out/pose.png ] || fail "drawings missing"
grep -q "^cMo:" out.txt || fail "no pose printed on the sample image: $(cat out.txt)"
pass "pose of the sample image, drawings written"

# Bad input: one line each, 2 for a bad option or camera file, 1 for an image that cannot be read.
check() {
  local expected="$1"
  shift
  "$BIN" "$@" > /dev/null 2> err
  local code=$?
  [ "$code" -eq "$expected" ] || fail "$*: exit code $code, expected $expected"
  [ "$(grep -c . err)" -eq 1 ] || fail "$*: expected one line on stderr, got: $(cat err)"
}
check 2 --window 1
check 2 --intrinsic missing.xml
check 2 --target no-such-target
check 2 --bogus
echo x > afile
check 2 --output afile --input "$DATA/images/ssl3-a3-00.png"
check 1 --input missing.png --output out2
[ "$(cat afile)" = x ] || fail "the file given as --output was overwritten"
pass "bad input: one line, documented exit status"

e2e_finish

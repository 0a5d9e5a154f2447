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

# A truncated JPEG: libjpeg's own warning ("Premature end of JPEG file"), which its default error manager prints
# on stderr, never reaches it; the tutorial's one line names the file and the problem, with exit status 1. The
# whole file (a 32 x 24 view of the sample image) reads; it is cut in its scan data, then before it.
base64 -d > small.jpg <<'JPEG'
/9j/4AAQSkZJRgABAQAAAQABAAD/2wBDABALDA4MChAODQ4SERATGCgaGBYWGDEjJR0oOjM9PDkzODdASFxOQERXRTc4UG1RV19i
Z2hnPk1xeXBkeFxlZ2P/wAALCAAYACABAREA/8QAHwAAAQUBAQEBAQEAAAAAAAAAAAECAwQFBgcICQoL/8QAtRAAAgEDAwIEAwUF
BAQAAAF9AQIDAAQRBRIhMUEGE1FhByJxFDKBkaEII0KxwRVS0fAkM2JyggkKFhcYGRolJicoKSo0NTY3ODk6Q0RFRkdISUpTVFVW
V1hZWmNkZWZnaGlqc3R1dnd4eXqDhIWGh4iJipKTlJWWl5iZmqKjpKWmp6ipqrKztLW2t7i5usLDxMXGx8jJytLT1NXW19jZ2uHi
4+Tl5ufo6erx8vP09fb3+Pn6/9oACAEBAAA/AM6KGWdtsMbyMBnCKScfhTWVkYqwKspwQRgg0lFa2is1vb395FjzIowAW+6qk8sR
1OAM4HXGKlsrnUrx5LO4uDJ9oiYqoKrtQjruCDvhdwBB35X7ppmu2qWdtZxCOJHw27YOe2AT1OOmT161j1ZtNQurJWW2kCBjk/Ip
J/EirFvqywfKtlbxofv/AGcGFm4I5Kn3NVru4W4FuscZRIIVhUM24kDuTgVXr//Z
JPEG
"$BIN" --input small.jpg --output out3 > /dev/null 2> small.err || fail "the whole JPEG: exit code $? $(cat small.err)"
head -c 400 small.jpg > cut-scan.jpg
head -c 200 small.jpg > cut-header.jpg
for cut in cut-scan cut-header; do
  expect_error 1 "$cut.jpg: JPEG data truncated or corrupt: Premature end of JPEG file" --input "$cut.jpg" --output out3
done
pass "truncated JPEG: one line, exit status 1"

e2e_finish

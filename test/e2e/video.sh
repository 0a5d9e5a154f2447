#!/usr/bin/env bash
# End-to-end check of the video and camera paths on a video the test writes with OpenCV (write_video: ssl3-a3
# rendered at 1.4 m to 0.7 m, MJPG AVI): tutorial-ssl-detector and tutorial-ssl-tracker read it frame by frame,
# tutorial-ssl-detector-live tracks it without an X display (annotated frames written instead), and a truncated
# video, a file that is no video and a camera that cannot be opened each give one line and exit status 1.
# Usage: video.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-detector-live "$@"
unset DISPLAY
WRITE_VIDEO="$BIN_DIR/../test/write_video"
CAMERA="$DATA/camera/camera-640x480.xml"

"$WRITE_VIDEO" clip.avi 12 || fail "write_video exit code $?"
[ -s clip.avi ] || { fail "no test video"; e2e_finish; }

# Detector: one JSON line per frame, named after the video, the target found in each.
"$BIN_DIR/tutorial-ssl-detector" --input clip.avi --camera "$CAMERA" --json --output det > det.jsonl 2> det.err ||
  fail "detector on a video: exit code $?"
python3 - det.jsonl <<'PY' || fail "detector on a video: JSON"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
assert len(lines) == 12, len(lines)
for n, o in enumerate(lines):
    assert o["image"] == "clip-%06d" % n, o["image"]
    assert o["target"]["found"], (n, o["target"])
PY
[ -f det/clip-000011.png ] || fail "detector on a video: annotated frame clip-000011.png missing"
pass "tutorial-ssl-detector reads the 12 frames of an AVI"

# A video cut in its middle: the frames before the cut are processed, then one line and status 1.
head -c "$(($(stat -c %s clip.avi) / 2))" clip.avi > cut.avi
"$BIN_DIR/tutorial-ssl-detector" --input cut.avi --json --output cut > cut.jsonl 2> cut.err
code=$?
[ "$code" -eq 1 ] || fail "truncated video: exit code $code, expected 1"
grep -q "cut.avi: .*\(ends at frame\|no frame\)" cut.err || fail "truncated video: no clear line: $(cat cut.err)"
[ "$(grep -c "cut.avi" cut.err)" -eq 1 ] || fail "truncated video: more than one error line: $(cat cut.err)"
[ "$(wc -l < cut.jsonl)" -ge 1 ] || fail "truncated video: the frames before the cut were not processed"
pass "a truncated video gives one line and status 1"

# A file that is no video.
echo "not a video" > fake.avi
"$BIN_DIR/tutorial-ssl-detector" --input fake.avi > /dev/null 2> fake.err
code=$?
[ "$code" -eq 1 ] || fail "not a video: exit code $code, expected 1"
[ "$(wc -l < fake.err)" -eq 1 ] && grep -q "fake.avi: " fake.err || fail "not a video: $(cat fake.err)"
pass "a file that is no video gives one line and status 1"

# Tracker on the video: a frame rate from the video, no ground truth; it reaches the tracking state.
"$BIN_DIR/tutorial-ssl-tracker" --video clip.avi --camera "$CAMERA" --csv track.csv > track.out 2> track.err ||
  fail "tracker on a video: exit code $? $(cat track.err)"
[ "$(($(wc -l < track.csv) - 1))" -eq 12 ] || fail "tracker on a video: expected 12 CSV rows"
grep -q ",tracking," track.csv || fail "tracker on a video: never tracking"
"$BIN_DIR/tutorial-ssl-tracker" --video clip.avi > /dev/null 2> nocam.err
[ $? -eq 2 ] || fail "tracker --video without --camera: expected status 2"
pass "tutorial-ssl-tracker tracks the target in the AVI"

# Live tutorial on the video file, without X: a one-line notice, every annotated frame written, a full pose.
"$BIN" --input clip.avi --intrinsic "$CAMERA" --output live > live.out 2> live.err || fail "live: exit code $?"
grep -q "no X display" live.err || fail "live: no notice of the file fallback"
[ "$(find live -name '*.png' | wc -l)" -eq 12 ] || fail "live: expected 12 annotated frames"
grep -q "tracking, range" live.out || fail "live: the tracker never reached the tracking state with a range"
grep -q "full pose in \([1-9]\|1[0-2]\)," live.err || fail "live: no full pose drawn: $(tail -n 1 live.err)"
pass "tutorial-ssl-detector-live tracks the AVI and writes the annotated frames"

# Cameras that cannot be opened: V4L2 and OpenCV; one line each, status 1.
for dev in /dev/video99 99; do
  "$BIN" --input "$dev" --intrinsic "$CAMERA" --output cam > /dev/null 2> cam.err
  code=$?
  [ "$code" -eq 1 ] || fail "camera $dev: exit code $code, expected 1"
  [ "$(grep -c . cam.err)" -eq 1 ] && grep -q "cannot open the camera" cam.err || fail "camera $dev: $(cat cam.err)"
done
pass "a camera that cannot be opened gives one line and status 1"

"$BIN" --help > help || fail "--help exit code"
for opt in --input --intrinsic --camera-name --target --max-frames --output --help; do
  grep -q -- "$opt" help || fail "--help does not mention $opt"
done
"$BIN" --max-frames 0 > /dev/null 2>&1
[ $? -eq 2 ] || fail "--max-frames 0: expected status 2"
pass "--help and bad options"

e2e_finish

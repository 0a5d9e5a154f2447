#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-record on a video the test writes with OpenCV (test/tools/write-test-video: an
# MJPG AVI of ssl3-a3 approaching from 2 m to 0.8 m): the recording with an odometry CSV conforms
# (tutorial-ssl-check-sequence), has the odometry interpolated to the image times, and runs through
# tutorial-ssl-tracker and tutorial-ssl-vs-apriltag; an image pattern records the same; bad input (a video ending
# early, a camera that cannot be opened, odometry out of order or not covering, a camera XML of another size, an
# output that is not empty) gives one line and the documented exit status.
# Usage: record.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-record "$@"
WRITE_VIDEO="$BIN_DIR/../test/write-test-video"
CAMERA="$DATA/camera/camera-640x480.xml"

"$BIN" --help > help || fail "--help exit code"
for opt in --input --camera --camera-name --output --odometry --camera-to-vehicle --target --rate --start-time \
           --first --frames --help; do
  grep -q -- "$opt" help || fail "--help does not mention $opt"
done

"$WRITE_VIDEO" dive.avi "$CAMERA" 12 10 || { fail "write-test-video"; e2e_finish; }
# Odometry at 5 Hz from before the first image (t = 100 s) to after the last (101.1 s): the vehicle moves 1 m/s
# North and turns at 0.5 rad/s about its z axis.
python3 - <<'PY'
import math
with open("odometry.csv", "w") as f:
    f.write("t,tx,ty,tz,qx,qy,qz,qw\n")
    for k in range(8):
        t = 99.9 + 0.2 * k
        yaw = 0.5 * (t - 100.0)
        f.write("%.3f,%.3f,0,2,0,0,%.12f,%.12f\n" % (t, t - 100.0, math.sin(yaw / 2), math.cos(yaw / 2)))
PY
MOUNT="0.5 0 0 1.20919958 1.20919958 1.20919958"
"$BIN" --input dive.avi --camera "$CAMERA" --odometry odometry.csv --camera-to-vehicle "$MOUNT" \
  --start-time 100 --output rec > out 2> err || fail "recording exit code $?: $(cat err)"
grep -q "12 frames written to rec with odometry" out || fail "summary line: $(cat out)"
"$BIN_DIR/tutorial-ssl-check-sequence" rec > check || fail "the recording does not conform: $(cat check)"
python3 - <<'PY' || fail "frames.csv: times and interpolated odometry"
import csv, json, math
rows = list(csv.DictReader(open("rec/frames.csv")))
assert len(rows) == 12, len(rows)
for i, r in enumerate(rows):
    # The video's 10 frames per second from --start-time, counted from the first image in t.
    t = float(r["stamp"])
    assert abs(t - (100 + i / 10)) < 1e-9, (i, t)
    assert abs(float(r["t"]) - i / 10) < 1e-9, (i, r["t"])
    # Linear in position and heading between the samples: the motion itself at the image's time, its origin at
    # the first sample's position (-0.1, 0, 2).
    assert abs(float(r["odom_tx"]) - (t - 100 + 0.1)) < 1e-6, r
    assert abs(float(r["odom_tz"])) < 1e-9, r
    assert abs(float(r["odom_tuz"]) - 0.5 * (t - 100)) < 1e-6, r
    assert r["gt_tx"] == "", r  # a recording has no ground truth
info = json.load(open("rec/sequence.json"))
assert info["source"] == "recorded" and info["target"] == "ssl3-a3", info
assert abs(info["camera_to_vehicle"][0] - 0.5) < 1e-12, info
PY
"$BIN_DIR/tutorial-ssl-tracker" --sequence rec --csv track.csv --quiet 2> err || fail "tracker: $(cat err)"
python3 - <<'PY' || fail "the tracker follows the recorded target"
import csv
rows = list(csv.DictReader(open("track.csv")))
assert len(rows) == 12
last = rows[-1]
assert last["state"] == "tracking", last["state"]
assert abs(float(last["tz"]) - 0.8) < 0.05, last["tz"]  # the video's last view is 0.8 m away
PY
"$BIN_DIR/tutorial-ssl-vs-apriltag" --output-dir va rec > va.log 2> err || fail "vs-apriltag: $(cat err)"
grep -q "no truth" va.log || fail "vs-apriltag does not report a recording without truth: $(head -12 va.log)"

# The same images as a numbered pattern.
"$BIN" --input 'rec/images/%06d.png' --rate 10 --camera "$CAMERA" --output from-pattern > out 2> err ||
  fail "pattern exit code: $(cat err)"
[ "$(tail -n +2 from-pattern/frames.csv | wc -l)" -eq 12 ] || fail "pattern: not 12 rows"
cmp -s rec/images/000011.png from-pattern/images/000011.png || fail "pattern: image 11 differs"

# Bad input: one line on stderr, the documented exit status, nothing the user gave overwritten.
expect_error 2 "are required" --input dive.avi
expect_error 2 "unknown option" --input dive.avi --camera "$CAMERA" --output x --bogus
expect_error 2 "needs --camera-to-vehicle" --input dive.avi --camera "$CAMERA" --output x --odometry odometry.csv
expect_error 2 "--rate is required" --input 'rec/images/%06d.png' --camera "$CAMERA" --output x
expect_error 2 "expected 6 numbers" --input dive.avi --camera "$CAMERA" --output x --camera-to-vehicle "1 2 3"
expect_error 1 "dive.avi: ended after 12 of the 20 frames asked" --input dive.avi --camera "$CAMERA" --output x1 \
  --frames 20
head -c 60000 dive.avi > cut.avi
expect_error 1 "cut.avi: ended after .* of the 12 frames it states" --input cut.avi --camera "$CAMERA" --output x2
expect_error 1 "no such video file" --input missing.avi --camera "$CAMERA" --output x3
expect_error 1 "/dev/video-none: cannot open the camera" --input /dev/video-none --camera "$CAMERA" --output x4
printf 't,tx,ty,tz,tux,tuy,tuz\n99,0,0,0,0,0,0\n101,1,0,0,0,0,0\n100,2,0,0,0,0,0\n' > unordered.csv
expect_error 1 "unordered.csv:4: t: not increasing" --input dive.avi --camera "$CAMERA" --output x5 \
  --odometry unordered.csv --camera-to-vehicle "$MOUNT" --start-time 100
expect_error 1 "odometry.csv: image 0 at t = 0.000000 s is outside the odometry's" --input dive.avi \
  --camera "$CAMERA" --output x6 --odometry odometry.csv --camera-to-vehicle "$MOUNT"
sed 's#<image_width>640#<image_width>320#; s#<image_height>480#<image_height>240#' "$CAMERA" > small.xml
expect_error 1 'is for 320x240 images, dive.avi gives 640x480' --input dive.avi --camera small.xml --output x7
[ ! -e x7 ] || fail "a refused recording left an output folder"
mkdir keep && echo "mine" > keep/notes.txt
expect_error 1 "keep: exists and is not an empty folder" --input dive.avi --camera "$CAMERA" --output keep
[ "$(ls keep)" = notes.txt ] && [ "$(cat keep/notes.txt)" = mine ] || fail "the non-empty output was touched"
e2e_finish

#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-rosbag on bags the test writes with rosbag_storage (test/tools/write-test-bag:
# views of ssl3-a3, CameraInfo, Odometry): --list, a conversion that conforms (tutorial-ssl-check-sequence) and
# runs through tutorial-ssl-tracker, compressed images, and bad input (a bag without the topic, not a bag, a topic
# of another type, odometry not covering the images, an output that is not empty) with one line and the
# documented exit status.
# Usage: rosbag.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-rosbag "$@"
WRITE_BAG="$BIN_DIR/../test/write-test-bag"

"$BIN" --help > help || fail "--help exit code"
for opt in --bag --list --image-topic --info-topic --odometry-topic --odometry-axes --camera-to-vehicle --target \
           --output --max-frames --help; do
  grep -q -- "$opt" help || fail "--help does not mention $opt"
done

"$WRITE_BAG" dive.bag --frames 6 || { fail "write-test-bag"; e2e_finish; }
"$BIN" --bag dive.bag --list > list 2> err || fail "--list exit code: $(cat err)"
grep -Eq '^/camera/image_raw +sensor_msgs/Image +6$' list || fail "--list: image topic: $(cat list)"
grep -Eq '^/camera/camera_info +sensor_msgs/CameraInfo +6$' list || fail "--list: info topic: $(cat list)"
grep -Eq '^/odom +nav_msgs/Odometry +12$' list || fail "--list: odometry topic: $(cat list)"

MOUNT="0.5 0 0 1.20919958 1.20919958 1.20919958"
TOPICS=(--image-topic /camera/image_raw --info-topic /camera/camera_info)
"$BIN" --bag dive.bag "${TOPICS[@]}" --odometry-topic /odom --camera-to-vehicle "$MOUNT" --output seq > out 2> err ||
  fail "conversion exit code: $(cat err)"
grep -q "6 frames of /camera/image_raw written to seq with odometry of /odom" out || fail "summary: $(cat out)"
"$BIN_DIR/tutorial-ssl-check-sequence" seq > check || fail "the conversion does not conform: $(cat check)"
grep -q "6 with odometry" check || fail "check-sequence: $(cat check)"
python3 - <<'PY' || fail "frames.csv: image stamps and odometry in North-East-Down"
import csv
rows = list(csv.DictReader(open("seq/frames.csv")))
assert len(rows) == 6
for i, r in enumerate(rows):
    t = float(r["stamp"])  # the image's header stamp; t counts from the first one
    assert abs(t - (1000.025 + 0.1 * i)) < 1e-6 and abs(float(r["t"]) - 0.1 * i) < 1e-6, (i, r)
    # The bag's vehicle sails East (ROS x) at a constant depth from the origin: North 0, East 0.5 t, Down 0.
    assert abs(float(r["odom_tx"])) < 1e-9 and abs(float(r["odom_ty"]) - 0.5 * (t - 1000)) < 1e-6, r
    assert abs(float(r["odom_tz"])) < 1e-9, r
PY
"$BIN_DIR/tutorial-ssl-tracker" --sequence seq --csv track.csv --quiet 2> err || fail "tracker: $(cat err)"
grep -q ",tracking," track.csv || fail "the tracker never tracks the bag's target"

"$WRITE_BAG" compressed.bag --compressed --no-odometry || fail "write-test-bag --compressed"
"$BIN" --bag compressed.bag "${TOPICS[@]}" --output seq-compressed --max-frames 3 > out 2> err ||
  fail "compressed conversion: $(cat err)"
[ "$(tail -n +2 seq-compressed/frames.csv | wc -l)" -eq 3 ] || fail "--max-frames 3: not 3 rows"
"$BIN_DIR/tutorial-ssl-check-sequence" seq-compressed > /dev/null || fail "compressed conversion does not conform"

expect_error 2 "--bag is required" --list
expect_error 2 "required to convert" --bag dive.bag
expect_error 2 "needs --camera-to-vehicle" --bag dive.bag "${TOPICS[@]}" --odometry-topic /odom --output x
expect_error 2 "--odometry-axes" --bag dive.bag --list --odometry-axes enu
expect_error 1 "dive.bag: /camera/image_rect: no such topic in the bag (.* topics: /camera/image_raw)" \
  --bag dive.bag --image-topic /camera/image_rect --info-topic /camera/camera_info --output x1
expect_error 1 "/odom: has type nav_msgs/Odometry, expected sensor_msgs/CameraInfo" \
  --bag dive.bag --image-topic /camera/image_raw --info-topic /odom --output x2
echo "not a bag" > not.bag
expect_error 1 "not.bag: cannot read the bag" --bag not.bag --list
"$WRITE_BAG" short.bag --odometry-end 0.15 || fail "write-test-bag --odometry-end"
expect_error 1 "short.bag: /camera/image_raw: image 2: odometry: time 1000.225000 is outside" \
  --bag short.bag "${TOPICS[@]}" --odometry-topic /odom --camera-to-vehicle "$MOUNT" --output x3
[ "$(tail -n +2 x3/frames.csv | wc -l)" -eq 2 ] || fail "the frames before the error are not kept"
expect_error 1 "seq: exists and is not an empty folder" --bag dive.bag "${TOPICS[@]}" --output seq
e2e_finish

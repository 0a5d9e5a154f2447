#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-detector: --help, the JSON Lines contract (doc/detection-json.md),
# annotated output, and one-line errors with the documented exit codes.
# Usage: detector.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
E2E_FAIL_FAST=1
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-detector "$@"

"$BIN" --help > "$WORK/help" || fail "--help exit code"
for opt in --input --camera --camera-name --target --json --output --display --window --small-landmarks --no-equal-rings --no-blur-model \
           --all-around-budget --decimation --threshold --no-normalize --threads --max-frames --help; do
  grep -q -- "$opt" "$WORK/help" || fail "--help does not mention $opt"
done

# Small-landmark mode sees B at 4.8 m (11.5 px) in the recorded clear-water approach.
"$BIN" --input "$DATA/sequences/approach-clear/images/000006.png" --small-landmarks --json --output "$WORK/small" \
  > "$WORK/small.jsonl" 2> /dev/null || fail "--small-landmarks exit code $?"
python3 -c 'import json,sys; t=json.load(open(sys.argv[1]))["target"]; assert t["found"] and "B" in t["landmarks"], t' \
  "$WORK/small.jsonl" || fail "--small-landmarks does not find B at 4.8 m"

# The fast mode reads B at 1.4 m (40.7 px) in the same approach (doc/detector.md, setDecimation(2)).
"$BIN" --input "$DATA/sequences/approach-clear/images/000010.png" --decimation 2 --json --output "$WORK/dec2" \
  > "$WORK/dec2.jsonl" 2> /dev/null || fail "--decimation 2 exit code $?"
python3 -c 'import json,sys; t=json.load(open(sys.argv[1]))["target"]; assert t["found"] and "B" in t["landmarks"], t' \
  "$WORK/dec2.jsonl" || fail "--decimation 2 does not find B at 1.4 m"

# A sequence of the demo images with a camera: one JSON object per image on stdout, nothing else.
"$BIN" --input "$DATA/images/ssl3-a3-%02d.png" --camera "$DATA/camera/camera-640x480.xml" --json \
  --output "$WORK/out" > "$WORK/seq.jsonl" 2> "$WORK/seq.err" || fail "sequence exit code $?"
[ "$(wc -l < "$WORK/seq.jsonl")" -eq 4 ] || fail "expected 4 JSON lines, got $(wc -l < "$WORK/seq.jsonl")"
for i in 00 01 02 03; do [ -f "$WORK/out/ssl3-a3-$i.png" ] || fail "annotated image $i missing"; done
python3 - "$WORK/seq.jsonl" <<'PY' || fail "JSON contract"
import json, sys
lines = open(sys.argv[1]).read().splitlines()
for n, line in enumerate(lines):
    o = json.loads(line)
    for k in ("image", "width", "height", "time_ms", "landmarks", "target"):
        assert k in o, (n, k)
    assert o["image"] == "ssl3-a3-%02d.png" % n, o["image"]
    assert (o["width"], o["height"]) == (640, 480)
    scores = [l["score"] for l in o["landmarks"]]
    assert scores == sorted(scores, reverse=True), "landmarks not best score first"
    for l in o["landmarks"]:
        assert set(l) >= {"u", "v", "radius_px", "score"} and 0 <= l["score"] <= 1
    t = o["target"]
    assert t["found"] is True and "cMo" in t and "range_m" in t, t
    assert set(t["landmarks"]) <= {"B", "S1", "S2"} and "B" in t["landmarks"]
    assert t["n_landmarks"] == len(t["landmarks"])
first, last = json.loads(lines[0]), json.loads(lines[-1])
assert first["target"]["n_landmarks"] == 3, first
# 2 m: S1 and S2 measure 14 px, below what w = 40 answers; the short window finds them, and the pose follows.
assert last["target"]["n_landmarks"] == 3, last
assert abs(last["target"]["range_m"] - 2.0) < 0.15, last  # to B's centre
assert last["target"]["cMo"] is not None, last
# Three landmarks and a camera: a pose (paper case 3). The demo poses are not stored: check plausibility.
import math
t = first["target"]
M = t["cMo"]
assert isinstance(M, list) and len(M) == 16, t
assert M[12:] == [0, 0, 0, 1], M
R = [[M[4 * i + j] for j in range(3)] for i in range(3)]
for i in range(3):
    for j in range(3):
        dot = sum(R[k][i] * R[k][j] for k in range(3))
        assert abs(dot - (1 if i == j else 0)) < 1e-4, ("rotation not orthonormal", R)
tx, ty, tz = M[3], M[7], M[11]
norm = math.sqrt(tx * tx + ty * ty + tz * tz)
assert tz > 0, M
assert abs(t["range_m"] - norm) < 2e-3, (t["range_m"], norm)
# |t| against Eq. 6 on the big landmark B (R = 0.1 m, px = 554.3) and the bearing of its centre.
u, v = t["landmarks"]["B"]
rB = [l["radius_px"] for l in first["landmarks"] if (l["u"], l["v"]) == (u, v)][0]
zB = 554.3 * 0.1 / rB
pB = [(u - 320) / 554.3 * zB, (v - 240) / 554.3 * zB, zB]
assert abs(norm - math.sqrt(sum(c * c for c in pB))) < 0.15 * norm, (norm, pB)
PY

# Without a camera there is no range and no pose.
"$BIN" --input "$DATA/images/ssl3-a3-00.png" --json > "$WORK/one.json" 2>/dev/null || fail "single image exit code"
python3 -c 'import json,sys; t=json.load(open(sys.argv[1]))["target"]; assert t["cMo"] is None and t["range_m"] is None' \
  "$WORK/one.json" || fail "no camera: cMo and range_m must be null"

# A file with no landmark: target not found, exactly as doc/detection-json.md writes it.
python3 -c 'import sys; open(sys.argv[1],"wb").write(b"P5\n64 48\n255\n" + bytes([128]*64*48))' "$WORK/grey.pgm"
"$BIN" --input "$WORK/grey.pgm" --json > "$WORK/grey.json" 2>/dev/null || fail "grey image exit code"
grep -q '"target": {"found": false, "n_landmarks": 0}' "$WORK/grey.json" || fail "not-found record: $(cat "$WORK/grey.json")"

# An unreadable image: an error record, one line on stderr, exit status 1.
echo "not an image" > "$WORK/broken.png"
"$BIN" --input "$WORK/broken.png" --json > "$WORK/broken.json" 2> "$WORK/broken.err"
[ $? -eq 1 ] || fail "unreadable image must exit 1"
python3 -c 'import json,sys; o=json.load(open(sys.argv[1])); assert o["image"]=="broken.png" and "error" in o' \
  "$WORK/broken.json" || fail "error record: $(cat "$WORK/broken.json")"
[ "$(grep -c . "$WORK/broken.err")" -ge 1 ] || fail "no message on stderr"

# Bad camera file, bad target file, bad option: exit 2 with one line on stderr naming the problem.
echo "<root><camera><name>Other</name></camera></root>" > "$WORK/cam.xml"
"$BIN" --input "$DATA/images/ssl3-a3-00.png" --camera "$WORK/cam.xml" > /dev/null 2> "$WORK/cam.err"
[ $? -eq 2 ] || fail "bad camera file must exit 2"
[ "$(wc -l < "$WORK/cam.err")" -eq 1 ] && grep -q "cam.xml" "$WORK/cam.err" || fail "camera error: $(cat "$WORK/cam.err")"
printf 'name t\nlandmark B 0 0 0 abc\n' > "$WORK/bad-target.txt"
"$BIN" --input "$DATA/images/ssl3-a3-00.png" --target "$WORK/bad-target.txt" > /dev/null 2> "$WORK/target.err"
[ $? -eq 2 ] || fail "bad target file must exit 2"
[ "$(wc -l < "$WORK/target.err")" -eq 1 ] && grep -q "bad-target.txt:2" "$WORK/target.err" ||
  fail "target error: $(cat "$WORK/target.err")"
"$BIN" --input x --window 500 > /dev/null 2> "$WORK/opt.err"
[ $? -eq 2 ] && [ "$(wc -l < "$WORK/opt.err")" -eq 1 ] || fail "bad window: $(cat "$WORK/opt.err")"
"$BIN" --input x --decimation 3 > /dev/null 2> "$WORK/dec.err"
[ $? -eq 2 ] && [ "$(wc -l < "$WORK/dec.err")" -eq 1 ] && grep -q -- "--decimation" "$WORK/dec.err" ||
  fail "bad decimation: $(cat "$WORK/dec.err")"
for bad in -1 100001 abc; do
  "$BIN" --input x --all-around-budget "$bad" > /dev/null 2> "$WORK/budget.err"
  [ $? -eq 2 ] && [ "$(wc -l < "$WORK/budget.err")" -eq 1 ] && grep -q -- "--all-around-budget" "$WORK/budget.err" ||
    fail "bad all-around budget $bad: $(cat "$WORK/budget.err")"
done
"$BIN" > /dev/null 2>&1
[ $? -eq 2 ] || fail "missing --input must exit 2"
e2e_finish

#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-tracker: --help, one-line errors with the documented exit codes, and a run
# on the sample sequence approach-clear (CSV header and rows, annotated images, summary table).
# Usage: tracker.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
E2E_FAIL_FAST=1
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-tracker "$@"

"$BIN" --help > "$WORK/help" || fail "--help exit code"
for opt in --sequence --csv --output-dir --display --no-odometry --small-landmarks --particles --seed \
           --full-search --max-frames --quiet --summary --help; do
  grep -q -- "$opt" "$WORK/help" || fail "--help does not mention $opt"
done

# Bad options: exit 2 and one line on stderr naming the problem.
expect_error 2 "--sequence is required"
expect_error 2 "unknown option" --sequence "$DATA/sequences/approach-clear" --bogus
expect_error 2 "needs a value" --sequence
expect_error 2 "--small-landmarks" --sequence "$DATA/sequences/approach-clear" --small-landmarks sometimes
expect_error 2 "--particles" --sequence "$DATA/sequences/approach-clear" --particles -3
expect_error 2 "--max-frames" --sequence "$DATA/sequences/approach-clear" --max-frames abc
expect_error 1 "no-such-sequence" --sequence "$WORK/no-such-sequence"

# A run on approach-clear: one CSV row per frame, the documented columns, annotated images, the summary.
"$BIN" --sequence "$DATA/sequences/approach-clear" --csv "$WORK/track.csv" --output-dir "$WORK/annotated" \
  --summary > "$WORK/log" 2> "$WORK/err" || fail "run exit code $?: $(cat "$WORK/err")"
[ -f "$WORK/annotated/000011.png" ] || fail "annotated image 000011.png missing"
grep -q "^| 0-1 |" "$WORK/log" || fail "no summary table in the output"
python3 - "$WORK/track.csv" <<'PY' || fail "CSV contract"
import csv, math, sys
rows = list(csv.reader(open(sys.argv[1])))
header = rows[0]
expected = ("frame,t,state,nb_points,full_search,small_mode,orientation_known,tx,ty,tz,tux,tuy,tuz,gt_tx,gt_ty,gt_tz,gt_tux,gt_tuy,"
            "gt_tuz,range,position_error,angle_error_deg,single_kind,single_position_error,"
            "single_angle_error_deg").split(",")
assert header == expected, header
rows = [dict(zip(header, r)) for r in rows[1:]]
assert len(rows) == 12, len(rows)
for i, r in enumerate(rows):
    assert int(r["frame"]) == i
    assert r["state"] in ("searching", "acquired", "tracking", "lost"), r["state"]
    has_pose = r["state"] != "searching"
    assert (r["tx"] != "") == has_pose, r
    for k in ("tx", "ty", "tz", "tux", "tuy", "tuz", "position_error", "angle_error_deg"):
        if r[k] != "":
            assert math.isfinite(float(r[k])), (k, r[k])
    assert r["gt_tz"] != "" and float(r["range"]) > 0  # the target is in view in every frame
    assert r["single_kind"] in ("", "full", "position")
    if r["single_kind"] == "full":
        assert r["single_angle_error_deg"] != ""
    assert r["small_mode"] in ("0", "1") and r["orientation_known"] in ("0", "1")
# The detector sees the target at the last three frames (2.2 m, 1.4 m, 0.5 m): a pose there, close to the truth.
assert rows[0]["state"] == "searching" and rows[0]["small_mode"] == "1"  # searching: small-landmark mode
last = rows[-1]
assert last["state"] in ("acquired", "tracking") and last["nb_points"] == "3", last
assert float(last["position_error"]) < 0.02, last["position_error"]
assert float(last["angle_error_deg"]) < 5, last["angle_error_deg"]
PY

# Without odometry, to standard output: the same number of rows.
"$BIN" --sequence "$DATA/sequences/approach-clear" --csv - --no-odometry --quiet > "$WORK/stdout.csv" 2> "$WORK/err" \
  || fail "--csv - exit code"
[ "$(wc -l < "$WORK/stdout.csv")" -eq 13 ] || fail "--csv -: expected 13 lines, got $(wc -l < "$WORK/stdout.csv")"
e2e_finish

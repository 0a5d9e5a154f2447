#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-vs-apriltag: help text, one-line errors, the report on the sample sequences
# (rows, rates, files), a recording without ground truth, and the baseline on ViSP's AprilTag benchmark image.
# Usage: bash vs_apriltag.sh TUTORIAL_BIN_DIR DATA_DIR   (run from a scratch directory)
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-vs-apriltag "$@"

SEQ="$DATA/sequences"

# --help: exit 0, names every option.
if "$BIN" --help >help.txt 2>help.err; then
  missing=""
  for o in --output-dir --max-frames --bin --apriltag-decimate --progress --quiet --check-visp-benchmark; do
    grep -q -- "$o" help.txt || missing="$missing $o"
  done
  [ -z "$missing" ] && pass "--help lists every option" || fail "--help does not list:$missing"
else
  fail "--help exited non-zero"
fi

# Bad arguments: exit status 2, exactly one line on stderr naming the problem.
expect_error 2 "no sequence" --quiet
expect_error 2 "--frobnicate" --frobnicate
expect_error 2 "--max-frames" "$SEQ/approach-clear" --max-frames
expect_error 2 "--bin" --bin abc "$SEQ/approach-clear"
expect_error 2 "no-such-dir" no-such-dir
mkdir -p notaseq
expect_error 2 "frames.csv" notaseq
# A malformed frames.csv: the reader's FILE:LINE: FIELD message on one line.
cp -r "$SEQ/approach-clear" broken
sed -i '4s/^\([0-9]*\),[^,]*,/\1,abc,/' broken/frames.csv
expect_error 2 "frames.csv:4" --quiet --output-dir out-broken broken

# The sample sequences: one row per sequence, per method, per water preset; files written.
if "$BIN" --quiet --output-dir out "$SEQ/approach-clear" "$SEQ/apriltag-approach-clear" "$SEQ/orbit-coastal-seabed" \
  >report.txt 2>run.err; then
  pass "runs on the sample sequences"
else
  fail "run on the sample sequences failed: $(cat run.err)"
fi
[ -s run.err ] && fail "stderr not empty with --quiet: $(cat run.err)"
cmp -s report.txt out/report.md && pass "stdout is report.md" || fail "stdout differs from out/report.md"
row() { grep -E "^\| $1 \| $2 \| $3 \|" report.txt; }
check_row() { # NAME METHOD WATER FRAMES
  local r
  r=$(row "$1" "$2" "$3")
  if [ -z "$r" ]; then
    fail "no row $1 / $2 / $3"
  elif ! echo "$r" | awk -F'|' -v n="$4" '{ gsub(/ /, "", $5); exit !($5 == n) }'; then
    fail "row $1 / $2: frames column is not $4: $r"
  else
    pass "row $1 / $2 / $3 with $4 frames"
  fi
}
check_row approach-clear SSL clear 12
check_row apriltag-approach-clear AprilTag clear 8
check_row orbit-coastal-seabed SSL coastal 8
check_row '\*\*all\*\*' SSL all 20
check_row '\*\*all\*\*' AprilTag all 8
check_row all SSL coastal 8
# Rates are n/N with N the frames in view; every row has 17 columns.
r=$(row apriltag-approach-clear AprilTag clear)
echo "$r" | grep -qE '\| [01]\.[0-9]{2} \([0-8]/8\) \|' && pass "AprilTag rate cell n/8" || fail "AprilTag rate cell: $r"
# The AprilTag sample is rendered up to 10 m: the baseline finds the tag at 0.5 to 4 m at least.
echo "$r" | awk -F'|' '{ for (i = 7; i <= 9; ++i) if ($i !~ /1\.00/) exit 1 }' && pass "AprilTag detects 0-4 m" ||
  fail "AprilTag misses the tag within 4 m: $r"
bad=$(grep -E '^\| ' report.txt | awk -F'|' 'NF != 20' | head -1)
[ -z "$bad" ] && pass "every table row has 18 cells" || fail "row with a wrong number of cells: $bad"
grep -q "Same views" report.txt && fail "the sample sequences are no pair, but a pair table was printed" ||
  pass "no pair among the samples"
for f in report.md summary.csv frames.csv rate_vs_range.png pose_error_vs_range.png; do
  [ -s "out/$f" ] && pass "wrote $f" || fail "did not write $f"
done
# Position-only poses (the SSL tracker on B alone, beyond 3.1 m in approach-clear) have no angle error: their
# angle cell is empty in frames.csv, they are left out of the angle median and counted apart in the report.
head -1 out/frames.csv | grep -q ',angle_err_deg,time_ms,orientation_known$' || fail "frames.csv header: $(head -1 out/frames.csv)"
awk -F, 'NR > 1 && $13 == 0 && $11 != "" { exit 1 }' out/frames.csv && pass "no angle error on position-only frames" ||
  fail "a position-only frame has an angle error: $(awk -F, 'NR > 1 && $13 == 0 && $11 != ""' out/frames.csv | head -1)"
np=$(awk -F, '$1 == "approach-clear" && $6 == 1 && $7 == 1 && $13 == 0' out/frames.csv | wc -l)
na=$(awk -F, '$1 == "approach-clear" && $6 == 1 && $7 == 1 && $13 == 1 && $11 != ""' out/frames.csv | wc -l)
cell=$(row approach-clear SSL clear | awk -F'|' '{ gsub(/ /, "", $16); print $16 }')
if [ "$np" -gt 0 ] && [ "$na" -gt 0 ] && [ "$cell" = "$np" ]; then
  pass "approach-clear: $np position-only frames counted apart, $na with an angle error"
else
  fail "approach-clear: position-only cell '$cell', frames.csv: $np position-only, $na with an angle error"
fi
median=$(awk -F, '$1 == "approach-clear" && $11 != "" { print $11 }' out/frames.csv | sort -g |
  awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
reported=$(row approach-clear SSL clear | awk -F'|' '{ gsub(/ /, "", $15); print $15 }')
near=$(awk -v a="$median" -v b="$reported" 'BEGIN { d = a - b; print (d < 0.006 && d > -0.006) ? 1 : 0 }')
[ "$near" = 1 ] && pass "angle median $reported deg is that of the frames with an orientation" ||
  fail "angle median $reported, frames with an orientation give $median"
grep -q ',position_only_frames$' out/summary.csv || fail "summary.csv header lacks position_only_frames"
n=$(($(wc -l <out/frames.csv) - 1))
[ "$n" -eq 28 ] && pass "frames.csv has 28 rows" || fail "frames.csv has $n rows, expected 28"
head -c 8 out/rate_vs_range.png | od -An -c | grep -q 'P   N   G' && pass "rate_vs_range.png is a PNG" ||
  fail "rate_vs_range.png is not a PNG"

# A pair: the same sequence.json but the target is reported side by side.
cp -r "$SEQ/approach-clear" pair-ssl
cp -r "$SEQ/approach-clear" pair-tag
sed -i 's/"target": "ssl3-a3"/"target": "apriltag36h11-a3"/' pair-tag/sequence.json
if "$BIN" --quiet --output-dir out-pair --max-frames 3 pair-ssl pair-tag >pair.txt 2>pair.err; then
  grep -q "Same views" pair.txt && [ "$(grep -cE '^\| pair-(ssl|tag) ' pair.txt)" -eq 4 ] &&
    pass "identical sequences but the sheet are reported side by side" || fail "pair not reported: $(cat pair.txt)"
else
  fail "pair run failed: $(cat pair.err)"
fi

# A recording without ground truth: rate and timing only.
cp -r "$SEQ/approach-clear" recorded
sed -i 's/"source": "simulated"/"source": "recorded"/' recorded/sequence.json
awk -F',' 'BEGIN { OFS = "," } NR == 1 { print; next } { for (i = 9; i <= 14; ++i) $i = ""; print }' \
  "$SEQ/approach-clear/frames.csv" >recorded/frames.csv
if "$BIN" --quiet --max-frames 6 --output-dir out-rec recorded >rec.txt 2>rec.err; then
  r=$(grep -E '^\| recorded \| SSL \| clear \|' rec.txt)
  echo "$r" | grep -q "no truth" && echo "$r" | awk -F'|' '{ gsub(/ /, "", $13); exit !($13 == "-") }' &&
    pass "recording without truth: rate and timing only" || fail "recording without truth: $r"
else
  fail "recording without ground truth failed: $(cat rec.err)"
fi

# The baseline on ViSP's own AprilTag benchmark image (visp-images-data), when installed.
VB=/usr/share/visp-images-data/ViSP-images/AprilTag/benchmark/640x480
if [ -f "$VB/tag36_11_640x480.png" ]; then
  if "$BIN" --check-visp-benchmark "$VB" >visp.txt 2>visp.err && [ "$(grep -cE '^\| [0-4] \|' visp.txt)" -eq 5 ]; then
    pass "baseline finds the 5 tags of ViSP's benchmark image"
  else
    fail "--check-visp-benchmark: $(cat visp.txt visp.err)"
  fi
else
  echo "skip: visp-images-data not installed"
fi
expect_error 2 "tag36_11_640x480.png" --check-visp-benchmark nowhere

e2e_finish

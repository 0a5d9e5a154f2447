#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-simulate-sequence: help text, one-line errors, byte-identical output for a
# seed, the sequence format (tutorial-ssl-check-sequence), AprilTag and wide-camera sequences, and frames
# without ground truth while the target is out of view.
# Usage: bash simulate_sequence.sh TUTORIAL_BIN_DIR DATA_DIR   (run from a scratch directory)
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-simulate-sequence "$@"

# The project's sequence checker (doc/sequence-format.md); it must be there, as the simulator is.
CHECKER="$BIN_DIR/tutorial-ssl-check-sequence"
[ -x "$CHECKER" ] || { echo "FAIL: no executable $CHECKER" >&2; exit 1; }
check_format() {
  if "$CHECKER" "$1" >check.out 2>&1; then
    pass "check-sequence $1: $(cat check.out)"
  else
    fail "check-sequence $1: $(cat check.out)"
  fi
}

# --help: exit 0, every option, scenario and water preset.
if "$BIN" --help >help.txt 2>help.err; then
  for word in --output --overwrite --scenario --water --camera --target --apriltag --frames --fps --ranges --seed \
    --background --supersampling --colour --help approach orbit spiral leave-return left-right reflection clear \
    coastal turbid seabed klimt solvay; do
    grep -q -- "$word" help.txt || fail "--help does not mention $word"
  done
  pass "--help"
else
  fail "--help exit code $?"
fi

# Bad input: exit status 2 and exactly one line on stderr naming the problem.
bad() {
  local expect="$1"
  shift
  "$BIN" "$@" >bad.out 2>bad.err
  local status=$?
  if [ "$status" -ne 2 ]; then
    fail "$* exited with $status, expected 2"
  elif [ "$(wc -l <bad.err)" -ne 1 ]; then
    fail "$*: stderr has $(wc -l <bad.err) lines: $(cat bad.err)"
  elif ! grep -q -- "$expect" bad.err; then
    fail "$*: stderr does not mention '$expect': $(cat bad.err)"
  else
    pass "$* -> $(cat bad.err)"
  fi
}
bad "output" --frames 2
bad "dive" --output o --scenario dive
bad "murky" --output o --water murky
bad "frames" --output o --frames 0
bad "fps" --output o --fps abc
bad "nope.xml" --output o --camera nope.xml
bad "no-such-image" --output o --background no-such-image.png
bad "ranges" --output o --ranges 5
bad "--bogus" --output o --bogus
bad "586" --output o --apriltag 600

# The same seed writes the same bytes; another seed other noise and odometry.
run() { "$BIN" --frames 4 --supersampling 1 --scenario left-right --water coastal --background seabed "$@" >/dev/null 2>run.err; }
if run --output a --seed 5 && run --output b --seed 5 && run --output c --seed 6; then
  if cmp -s a/frames.csv b/frames.csv && cmp -s a/sequence.json b/sequence.json && cmp -s a/camera.xml b/camera.xml &&
    diff -r -q a/images b/images >/dev/null; then
    pass "same seed, byte-identical sequence"
  else
    fail "two runs with seed 5 differ"
  fi
  cmp -s a/frames.csv c/frames.csv && fail "seeds 5 and 6 give the same frames.csv"
  cmp -s a/images/000003.png c/images/000003.png && fail "seeds 5 and 6 give the same image"
  check_format a
  head -1 a/frames.csv | grep -q ',gt_B_u,gt_B_v,gt_S1_u,gt_S1_v,gt_S2_u,gt_S2_v,range,water,true_odom_tx,' ||
    fail "frames.csv header lacks the extra columns: $(head -1 a/frames.csv)"
  grep -q '"scenario": "left-right"' a/sequence.json || fail "sequence.json does not name the scenario"
else
  fail "simulating left-right failed: $(cat run.err)"
fi

# Refuses to overwrite a sequence unless told.
"$BIN" --frames 2 --supersampling 1 --output a >/dev/null 2>over.err
status=$?
if [ "$status" -eq 2 ] && [ "$(wc -l <over.err)" -eq 1 ]; then
  pass "refuses a non-empty folder: $(cat over.err)"
else
  fail "writing into a non-empty folder: status $status, stderr $(cat over.err)"
fi
"$BIN" --frames 2 --supersampling 1 --output a --overwrite >/dev/null 2>&1 || fail "--overwrite refused"

# The target leaves the view: rows without ground truth between rows with it.
if "$BIN" --scenario leave-return --frames 20 --supersampling 1 --output lr >/dev/null 2>lr.err; then
  pattern=$(awk -F, 'NR > 1 { printf "%s", ($9 == "" ? "-" : "g") }' lr/frames.csv)
  if [[ "$pattern" =~ ^g+-+g+$ ]]; then
    pass "leave-return ground truth: $pattern"
  else
    fail "leave-return ground truth pattern $pattern, expected g...-...g"
  fi
  check_format lr
else
  fail "leave-return failed: $(cat lr.err)"
fi

# AprilTag sheet and the wide camera file.
if "$BIN" --apriltag 3 --frames 2 --supersampling 1 --camera "$DATA/camera/camera-640x480-wide.xml" --output at \
  >/dev/null 2>at.err; then
  grep -q '"target": "apriltag36h11-a3-id3"' at/sequence.json || fail "AprilTag sequence.json: $(head -3 at/sequence.json)"
  head -1 at/frames.csv | grep -q ',gt_c0_u,gt_c0_v,gt_c1_u,' || fail "AprilTag corner columns missing"
  grep -q 'perspectiveProjWithDistortion' at/camera.xml || fail "wide camera.xml has no distortion"
  grep -q '<kud>' at/camera.xml || fail "wide camera.xml has no kud"
  check_format at
  pass "AprilTag sequence with the wide camera"
else
  fail "AprilTag run failed: $(cat at.err)"
fi
"$BIN" --frames 1 --supersampling 1 --camera "$DATA/camera/camera-640x480.xml" --output cam --colour >/dev/null 2>&1 ||
  fail "data/camera/camera-640x480.xml is not accepted"

e2e_finish

#!/usr/bin/env bash
# End-to-end check of scripts/benchmark-single-frame.sh on data/sequences/approach-clear: the table's header, one
# row for the sequence and one for all, its rate counted from tutorial-ssl-detector's own JSON Lines, and the bands'
# frames adding up to the sequence's.
# Usage: benchmark_single_frame.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
E2E_FAIL_FAST=1
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-detector "$@"
script="$(dirname "${BASH_SOURCE[0]}")/../../scripts/benchmark-single-frame.sh"
seq="$DATA/sequences/approach-clear"

TUTORIAL_DIR="$BIN_DIR" bash "$script" "$seq" >table.md 2>table.err || fail "exit code $?: $(cat table.err)"
"$BIN" --input "$seq/images/%06d.png" --json --threads 1 --output annotated >own.jsonl 2>/dev/null ||
  fail "tutorial-ssl-detector exit code $?"
python3 - table.md own.jsonl "$seq/frames.csv" <<'PY' 2>check.err && pass "table: $(sed -n 3p table.md)" || fail "$(cat check.err)"
import csv, json, re, sys
lines = open(sys.argv[1]).read().splitlines()
assert lines[0].startswith("| sequence | method | rate | 0-1 m |"), lines[0]
assert len(lines) == 4, "expected header, rule and 2 rows, got %d lines" % len(lines)
found = sum(json.loads(l)["target"]["found"] for l in open(sys.argv[2]))
frames = sum(1 for r in csv.DictReader(open(sys.argv[3])) if r["gt_B_u"] != "")
for line in lines[2:]:
    m = re.search(r"\| ([0-9.]+) \((\d+)/(\d+)\) \|", line)
    assert m, line
    assert (int(m.group(2)), int(m.group(3))) == (found, frames), "%s: expected %d/%d" % (line, found, frames)
    bands = re.findall(r"\| (\d+)/(\d+) ", line)
    assert sum(int(b[1]) for b in bands) == frames, "bands do not add up to %d frames: %s" % (frames, line)
    assert sum(int(b[0]) for b in bands) == found, "bands do not add up to %d found: %s" % (found, line)
PY
TUTORIAL_DIR="$BIN_DIR" bash "$script" "$WORK/nosuch" >/dev/null 2>err.txt && fail "a missing sequence exits 0"
grep -q "no frames.csv" err.txt && pass "a missing sequence: one line on stderr" || fail "missing sequence: $(cat err.txt)"
e2e_finish

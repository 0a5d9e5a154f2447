#!/usr/bin/env bash
# The single-frame SSL detector on recorded sequences: every frame searched whole, no tracking; a frame counts when
# the detector's JSON Lines say "target": {"found": true}. Prints one Markdown row per sequence and one for all:
# the rate over the frames with ground truth, the rate per range band (frames.csv's range column; 8-12 m takes
# 12 m), and the frames found without a target (frames.csv rows whose gt_B_u is empty) over those frames.
# doc/benchmarks.md shows the table for the sequences of scripts/benchmark-sequences.sh.
# Usage: scripts/benchmark-single-frame.sh SEQUENCE_DIR...   (TUTORIAL_DIR: the tutorials, default build/tutorial)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

if [ $# -eq 0 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then
  sed -n '2,7p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  [ $# -eq 0 ] && exit 2 || exit 0
fi
detector="${TUTORIAL_DIR:-$VISP_SSL_ROOT/build/tutorial}/tutorial-ssl-detector"
[ -x "$detector" ] || {
  echo "benchmark-single-frame.sh: $detector not built (cmake --build build --target tutorial-ssl-detector)" >&2
  exit 1
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Work files by position on the command line: two sequences may share a folder name.
i=0
for seq in "$@"; do
  [ -f "$seq/frames.csv" ] && [ -d "$seq/images" ] || {
    echo "benchmark-single-frame.sh: $seq: no frames.csv or images/ (doc/sequence-format.md)" >&2
    exit 1
  }
  "$detector" --input "$seq/images/%06d.png" --json --threads 1 --output "$work/$i-annotated" \
    >"$work/$i.jsonl" 2>"$work/$i.err" || {
    echo "benchmark-single-frame.sh: $seq: $(tail -n 1 "$work/$i.err")" >&2
    exit 1
  }
  i=$((i + 1))
done

python3 - "$work" "$@" <<'PY'
import csv, json, os, sys
work, seqs = sys.argv[1], sys.argv[2:]
bands = [(0, 1), (1, 2), (2, 4), (4, 8), (8, 12)]
def cell(n, d):
    return "%d/%d" % (n, d) if d else "-"
def print_row(label, t):
    rate = "%.2f (%d/%d)" % (t["found"] / t["frames"], t["found"], t["frames"]) if t["frames"] else "-"
    false = "%d / %d" % (t["false"], t["empty"]) if t["empty"] else "-"
    print("| %s | SSL detector, single frame | %s | %s | %s |" % (label, rate,
          " | ".join(cell(n, d) for n, d in t["band"]), false))
total = {"found": 0, "frames": 0, "band": [[0, 0] for _ in bands], "false": 0, "empty": 0}
print("| sequence | method | rate | " + " | ".join("%d-%d m" % b for b in bands) + " | false det. / frames w/o target |")
print("|---" * (len(bands) + 4) + "|")
for i, seq in enumerate(seqs):
    name = os.path.basename(os.path.normpath(seq))
    found = {}
    with open(os.path.join(work, "%d.jsonl" % i)) as f:
        for line in f:
            d = json.loads(line)
            found[d["image"]] = bool(d["target"]["found"])
    s = {"found": 0, "frames": 0, "band": [[0, 0] for _ in bands], "false": 0, "empty": 0}
    with open(os.path.join(seq, "frames.csv")) as f:
        for row in csv.DictReader(f):
            hit = found.get("%06d.png" % int(row["frame"]), False)
            if row["gt_B_u"] == "":
                s["empty"] += 1
                s["false"] += hit
                continue
            s["frames"] += 1
            s["found"] += hit
            r = float(row["range"])
            for k, (lo, hi) in enumerate(bands):
                if lo <= r < hi or (k == len(bands) - 1 and r == hi):
                    s["band"][k][0] += hit
                    s["band"][k][1] += 1
    for key in ("found", "frames", "false", "empty"):
        total[key] += s[key]
    for k in range(len(bands)):
        total["band"][k][0] += s["band"][k][0]
        total["band"][k][1] += s["band"][k][1]
    print_row(name, s)
print_row("**all**", total)
PY

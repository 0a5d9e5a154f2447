#!/usr/bin/env bash
# Generates the SSL vs AprilTag benchmark sequences and runs tutorial-ssl-vs-apriltag on them.
#
# Usage: scripts/benchmark-sequences.sh [OUT_DIR] [FRAMES]
#   OUT_DIR  where the sequences and the report go (default out/benchmark-sequences); nothing is committed.
#   FRAMES   frames per approach sequence (default 120; 20 for a quick look).
# Environment: TUTORIAL_DIR, the folder holding the built tutorials (default build/tutorial).
#
# For each water preset (clear 10 m, coastal 4 m, turbid 2 m visibility) two sequences identical but for the
# printed A3 sheet: ssl3-a3 and AprilTag 36h11 id 0 (same scenario, path, seed, noise and water), an approach
# from 12 m to 0.5 m; plus one pair of the leave-return scenario in clear water, whose frames with the target
# out of view count false detections. Every sequence is regenerated from its seed (deterministic).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
OUT="${1:-$VISP_SSL_ROOT/out/benchmark-sequences}"
FRAMES="${2:-120}"
BIN="${TUTORIAL_DIR:-$VISP_SSL_ROOT/build/tutorial}"
SIM="$BIN/tutorial-ssl-simulate-sequence"
BENCH="$BIN/tutorial-ssl-vs-apriltag"
for exe in "$SIM" "$BENCH"; do
  [ -x "$exe" ] || { echo "benchmark-sequences.sh: $exe not built (set TUTORIAL_DIR)" >&2; exit 1; }
done
case "$FRAMES" in '' | *[!0-9]*) echo "benchmark-sequences.sh: FRAMES must be a whole number" >&2; exit 1 ;; esac
mkdir -p "$OUT"

seqs=()
simulate() { # NAME SHEET_OPTION... -- SIM_OPTIONS...
  local name="$1"
  shift
  echo "== $name" >&2
  "$SIM" --output "$OUT/$name" --overwrite "$@" >/dev/null
  seqs+=("$OUT/$name")
}

seed=10
for water in clear coastal turbid; do
  seed=$((seed + 1))
  common=(--scenario approach --water "$water" --ranges 12,0.5 --frames "$FRAMES" --fps 10 --seed "$seed")
  simulate "approach-$water-ssl" "${common[@]}"
  simulate "approach-$water-apriltag" --apriltag 0 "${common[@]}"
done
common=(--scenario leave-return --water clear --frames $((FRAMES / 2)) --fps 10 --seed 20)
simulate "leave-return-clear-ssl" "${common[@]}"
simulate "leave-return-clear-apriltag" --apriltag 0 "${common[@]}"

"$BENCH" --output-dir "$OUT/report" "${seqs[@]}"
echo "report: $OUT/report/report.md, plots: $OUT/report/*.png" >&2

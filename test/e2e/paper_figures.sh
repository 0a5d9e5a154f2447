#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-paper-figures (--quick): help, one-line errors, every PNG written, and the
# claims of the paper's Fig. 2 and Fig. 4 read back from figures.md.
# Usage: bash paper_figures.sh TUTORIAL_BIN_DIR DATA_DIR   (run from a scratch directory)
set -u

BIN="$1/tutorial-ssl-paper-figures"
DATA="$2"
WORK=$(mktemp -d "$PWD/paper_figures.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1

FAILS=0
fail() {
  echo "FAIL: $*" >&2
  FAILS=$((FAILS + 1))
}
pass() { echo "ok: $*"; }
[ -x "$BIN" ] || { echo "FAIL: no executable $BIN" >&2; exit 1; }

if "$BIN" --help >help.txt 2>&1; then
  for o in --output-dir --sequence --quick; do grep -q -- "$o" help.txt || fail "--help does not list $o"; done
  pass "--help"
else
  fail "--help exited non-zero"
fi
expect_error() { # WHAT PATTERN ARGS...
  local what="$1" pattern="$2"
  shift 2
  "$BIN" "$@" >err.out 2>err.txt
  local status=$?
  if [ "$status" -ne 2 ]; then
    fail "$what: exit status $status, expected 2 (bad option or input)"
  elif [ "$(wc -l <err.txt)" -ne 1 ] || ! grep -q -- "$pattern" err.txt; then
    fail "$what: stderr: $(cat err.txt)"
  else
    pass "$what -> $(cat err.txt)"
  fi
}
expect_error "unknown argument" "--bogus" --bogus
expect_error "missing value" "--sequence" --sequence
expect_error "not a sequence" "frames.csv" --sequence "$WORK" --quick

if "$BIN" --quick --output-dir out --sequence "$DATA/sequences/approach-clear" >out.txt 2>err.txt; then
  pass "runs"
else
  fail "run failed: $(cat err.txt)"
fi
for f in fig2-rotation fig2-tilt fig2-blur-0 fig2-blur-45 fig2-contrast fig4-window fig5-size; do
  if [ -s "out/$f.png" ] && head -c 8 "out/$f.png" | od -An -c | grep -q 'P   N   G'; then
    pass "$f.png"
  else
    fail "$f.png missing or not a PNG"
  fi
done
cmp -s out.txt out/figures.md && pass "stdout is figures.md" || fail "stdout differs from figures.md"
# Fig. 2 row 1: the circular landmark is rotation invariant, the linear one (+x only) is lost when turned.
awk -F'|' '$2 ~ /rotation/ { c = $6 + 0; l = $4 + 0; if (n == 0 || c < cmin) cmin = c; if (n == 0 || c > cmax) cmax = c;
  if (n == 0 || l < lmin) lmin = l; n++ } END { exit !(n >= 3 && cmin > 0.5 && cmax - cmin < 0.01 && lmin < 0.1) }' out.txt &&
  pass "Fig. 2: circular rotation invariant, linear +x lost when turned" || fail "Fig. 2 rotation rows: $(grep rotation out.txt)"
# Fig. 2 row 3: under horizontal blur the circular landmark keeps more response than the linear one.
awk -F'|' '$2 ~ /blur-0/ && $3 + 0 > 5 { if (!($6 > $5 + 0.1)) bad = 1; n++ } END { exit !(n > 0 && !bad) }' out.txt &&
  pass "Fig. 2: circular beats linear under horizontal blur" || fail "Fig. 2 blur rows: $(grep blur-0 out.txt)"
# Fig. 4: the Eq. 7 sweep peaks at a fixed multiple of the radius (1 / sqrt(p) = 1.41 for p = 0.5).
awk -F'|' '$2 ~ /^ (20|40|60) $/ { gsub(/ /, "", $4); if ($4 < 0.9 || $4 > 1.6) bad = 1; n++ } END { exit !(n == 3 && !bad) }' \
  out.txt && pass "Fig. 4: peak proportional to the radius" || fail "Fig. 4 rows: $(grep -A5 'Fig. 4' out.txt)"
grep -q '^| 640x480 | [0-9]' out.txt && pass "Table 1 row 640x480" || fail "Table 1 missing"

if [ "$FAILS" -ne 0 ]; then
  echo "$FAILS check(s) failed" >&2
  exit 1
fi
echo "all checks passed"

#!/usr/bin/env bash
# End-to-end check of tutorial-ssl-target-generator: help text, the three outputs at 1:1 scale,
# PNG size and pixel colours against the pattern of Eq. 1, errors on one stderr line, --linear.
# Usage: bash target_generator.sh TUTORIAL_BIN_DIR DATA_DIR   (run from a scratch directory)
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-target-generator "$@"

# "W H" of the first /MediaBox of a PDF (cairo writes the page dictionary uncompressed).
mediabox() { grep -a -o '/MediaBox *\[[^]]*\]' "$1" | head -1 | tr -d '[]' | awk '{print $4, $5}'; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
# "W H" from the PNG IHDR: bytes 16-23, two big-endian 32-bit integers.
pngsize() {
  od -An -tu1 -j16 -N8 "$1" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }'
}

# --help: exit 0 and every option documented.
if "$BIN" --help >help.txt 2>help.err; then
  for opt in --target --output --dpi --linear --min-ring-mm --help; do
    grep -q -- "$opt" help.txt || fail "--help does not mention $opt"
  done
  pass "--help"
else
  fail "--help exit code $?"
fi

# An output prefix in folders that do not exist yet: they are made.
if "$BIN" --dpi 20 --output new/folder/sheet >mk.out 2>mk.err; then
  for ext in pdf svg png; do
    [ -s "new/folder/sheet.$ext" ] || fail "new/folder/sheet.$ext not written"
  done
  pass "--output into folders that do not exist yet"
else
  fail "--output new/folder/sheet: exit code $?: $(cat mk.err)"
fi

# Default target, PNG at 100 dpi.
if "$BIN" --dpi 100 >gen.out 2>gen.err; then
  for ext in pdf svg png; do
    [ -s "ssl3-a3.$ext" ] || fail "ssl3-a3.$ext not written"
  done
  read -r W H <<<"$(mediabox ssl3-a3.pdf)"
  if near "${W:-0}" 1190.55 0.5 && near "${H:-0}" 841.89 0.5; then
    pass "PDF MediaBox $W x $H pt (A3 landscape, 1:1)"
  else
    fail "PDF MediaBox '${W:-?} x ${H:-?}', expected 1190.55 x 841.89"
  fi
  grep -q 'width="1190.55[0-9]*pt" height="841.88[0-9]*pt"' ssl3-a3.svg || fail "SVG size is not 1190.55pt x 841.89pt"
  read -r PW PH <<<"$(pngsize ssl3-a3.png)"
  if near "${PW:-0}" 1654 1 && near "${PH:-0}" 1169 1; then
    pass "PNG $PW x $PH px at 100 dpi"
  else
    fail "PNG '${PW:-?} x ${PH:-?}', expected 1654 x 1169"
  fi
  [ -s gen.err ] && fail "unexpected stderr: $(cat gen.err)"
else
  fail "generating ssl3-a3 failed: $(cat gen.err)"
fi

# Pixel colours of the PNG against the ring layout of Eq. 1 (needs python3; zlib only).
if command -v python3 >/dev/null 2>&1 && [ -s ssl3-a3.png ]; then
  if python3 - ssl3-a3.png 100 >pix.out 2>&1 <<'EOF'; then
import math, struct, sys, zlib
path, dpi = sys.argv[1], float(sys.argv[2])
data = open(path, 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
pos, idat, w = 8, b'', 0
while pos < len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b'IHDR':
        w, h, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', body)
        assert depth == 8 and ctype in (2, 6) and interlace == 0, 'unexpected PNG layout'
        bpp = 3 if ctype == 2 else 4
    elif kind == b'IDAT':
        idat += body
    pos += 12 + n
raw, stride = zlib.decompress(idat), w * bpp
rows, prev = [], bytearray(stride)
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line); prev = line
k = dpi / 0.0254
x0, y0 = -0.051 - 0.21, -0.1485          # ssl3-a3 sheet corner in the target frame (doc/target-ssl3-a3.md)
def grey(X, Y):
    u, v = int(math.floor((X - x0) * k)), int(math.floor((Y - y0) * k))
    return rows[v][u * bpp]
bad = 0
for name, cx, cy, R in (('B', -0.103923, 0., 0.1), ('S1', 0.051962, -0.09, 0.05), ('S2', 0.051962, 0.09, 0.05)):
    for ring in range(6):              # ring k spans (R 2^-(k+1)/2, R 2^-k/2]: black when k is even
        r = R * 0.5 ** (ring / 2.) * (1 + math.sqrt(0.5)) / 2
        for ang in range(0, 360, 45):
            g = grey(cx + r * math.cos(math.radians(ang)), cy + r * math.sin(math.radians(ang)))
            want = 0 if ring % 2 == 0 else 255
            if abs(g - want) > 40:
                print(f'{name} ring {ring} at {ang} deg: grey {g}, expected {want}'); bad += 1
for X, Y in ((0., 0.), (0.14, 0.), (-0.104, 0.125)):  # paper between the discs
    if grey(X, Y) < 215:
        print(f'paper at ({X}, {Y}) is grey {grey(X, Y)}'); bad += 1
print(f'{bad} wrong pixels')
sys.exit(1 if bad else 0)
EOF
    pass "PNG pixels match the ring layout ($(tail -1 pix.out))"
  else
    fail "PNG pixels: $(tr '\n' ';' <pix.out)"
  fi
else
  echo "skip: pixel check (no python3)"
fi

# Another target from a file, custom prefix.
if "$BIN" --target "$DATA/targets/ssl1-single.txt" --output single --dpi 50 >single.out 2>single.err &&
  [ -s single.pdf ] && [ -s single.svg ] && [ -s single.png ]; then
  read -r W H <<<"$(mediabox single.pdf)"
  near "${W:-0}" 595.28 0.5 && near "${H:-0}" 841.89 0.5 || fail "ssl1-single MediaBox '$W x $H' (A4 portrait)"
  [ -s single.err ] && fail "ssl1-single: unexpected stderr (labels overlap the pattern?): $(cat single.err)"
  pass "--target FILE --output PREFIX"
else
  fail "--target ssl1-single.txt: $(cat single.err)"
fi

# Errors: exit status 2 and exactly one line on stderr naming the problem.
expect_error() { # $1 description, $2 text expected on stderr, rest: arguments
  local what="$1" want="$2"
  shift 2
  "$BIN" "$@" >err.out 2>err.txt
  local status=$?
  if [ "$status" -ne 2 ]; then
    fail "$what: exit status $status, expected 2 (bad option or input)"
  elif [ "$(wc -l <err.txt)" -ne 1 ]; then
    fail "$what: stderr has $(wc -l <err.txt) lines: $(tr '\n' '|' <err.txt)"
  elif ! grep -q -F -- "$want" err.txt; then
    fail "$what: stderr '$(cat err.txt)' does not contain '$want'"
  else
    pass "$what -> $(cat err.txt)"
  fi
}
printf 'name bad\nlanmark B 0 0 0 0.1\n' >bad.txt
expect_error "bad target file" 'bad.txt:2: unknown keyword "lanmark"' --target bad.txt --output bad
printf 'name bad\nlandmark B 0 0 0 abc\n' >bad2.txt
expect_error "bad radius" 'bad2.txt:2: radius: not a number: "abc"' --target bad2.txt --output bad
expect_error "missing target file" "nothing.txt: cannot open" --target nothing.txt
expect_error "unknown option" '"--bogus"' --bogus
expect_error "bad --dpi" "--dpi" --dpi 0
expect_error "bad --min-ring-mm" "--min-ring-mm" --min-ring-mm -1
expect_error "--dpi without value" "--dpi" --dpi
expect_error "--linear with --target" "--linear" --linear --target ssl3-a3
[ -e bad.pdf ] && fail "a PDF was written for a bad target file"

# The original linear landmark (Fig. 1a) on A4 landscape.
if "$BIN" --linear --dpi 50 >lin.out 2>lin.err && [ -s ssl-linear.pdf ] && [ -s ssl-linear.svg ] &&
  [ -s ssl-linear.png ]; then
  read -r W H <<<"$(mediabox ssl-linear.pdf)"
  if near "${W:-0}" 841.89 0.5 && near "${H:-0}" 595.28 0.5; then
    pass "--linear (A4 $W x $H pt)"
  else
    fail "--linear MediaBox '$W x $H'"
  fi
else
  fail "--linear: $(cat lin.err)"
fi
[ -s lin.err ] && fail "--linear: unexpected stderr: $(cat lin.err)"

e2e_finish

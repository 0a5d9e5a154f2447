#!/usr/bin/env bash
# Hostile input to the tutorials: every bad option, image, camera, target or sequence gives the documented exit
# status and one line on stderr naming the problem; never a crash, an abort, a sanitizer report, a hang or an
# allocation bomb; nothing the user gave is overwritten; output that could not be written whole is an error.
# Usage: hostile_input.sh TUTORIAL_BIN_DIR DATA_DIR (run from a scratch directory).
set -u
T="$1"
D="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
# Bounded memory and time: an allocation bomb or a hang fails the test instead of the machine. AddressSanitizer
# reserves terabytes of address space, so under it the bound is its own RSS limit instead of ulimit -v.
if ldd "$T/tutorial-ssl-detector" 2>/dev/null | grep -q libasan; then
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}hard_rss_limit_mb=8000"
else
  ulimit -v 8000000 2>/dev/null || true
fi

# expect STATUS PATTERN CMD...: CMD exits with STATUS, its stderr matches PATTERN (grep -E) and has no sanitizer
# report, no abort and, for status 2, exactly one line.
expect() {
  local status="$1" pattern="$2"
  shift 2
  timeout 120 "$@" >"$work/_stdout" 2>"$work/_stderr"
  local got=$?
  if [ "$got" -ne "$status" ]; then
    cat "$work/_stderr" >&2
    fail "$* exited $got, expected $status"
  fi
  [ -z "$pattern" ] || grep -Eq -e "$pattern" "$work/_stderr" || {
    cat "$work/_stderr" >&2
    fail "$*: stderr does not match '$pattern'"
  }
  if grep -Eq "AddressSanitizer|LeakSanitizer|runtime error:|terminate called|Aborted" "$work/_stderr"; then
    cat "$work/_stderr" >&2
    fail "$*: sanitizer report or abort"
  fi
  if [ "$status" -eq 2 ] && [ "$(wc -l <"$work/_stderr")" -ne 1 ]; then
    cat "$work/_stderr" >&2
    fail "$*: expected one line on stderr"
  fi
}

det="$T/tutorial-ssl-detector"
trk="$T/tutorial-ssl-tracker"
vs="$T/tutorial-ssl-vs-apriltag"
sim="$T/tutorial-ssl-simulate-sequence"
gen="$T/tutorial-ssl-target-generator"
chk="$T/tutorial-ssl-check-sequence"
rec="$T/tutorial-ssl-record"
img="$D/images/ssl3-a3-00.png"

# 1. An image whose width x height wraps vpImage's 32-bit size.
python3 -c "open('w.pgm','wb').write(b'P5\n65537 65536\n255\n'+b'\x80'*65536)"
expect 1 "w.pgm: PGM header: 65537 x 65536 pixels: a side exceeds the limit of 16384" "$det" --input w.pgm
# 2. A small PNG whose header declares 65536 x 65537 pixels; 12. one that declares 20000 x 20000.
python3 - <<'PY'
import struct, zlib
def png(w, h, rows):
    def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    raw = b''.join(b'\0' + b'\x80' * 4 for _ in range(rows))
    return b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 0, 0, 0, 0)) + \
        chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
open('lie.png', 'wb').write(png(65536, 65537, 4))
open('big.png', 'wb').write(png(20000, 20000, 4))
PY
expect 1 "lie.png: PNG header: 65536 x 65537 pixels" "$det" --input lie.png
expect 1 "big.png: PNG header: 20000 x 20000 pixels" "$det" --input big.png
# 3. A pattern whose expansion is longer than any path.
expect 2 "the only conversion a pattern may hold is %d" "$det" --input 'x/%09999d.png'
# 6. --output over an existing file, --display without an X server.
echo keep >existing
expect 2 "--output: existing: exists and is not a folder" "$det" --input "$img" --output existing
[ "$(cat existing)" = keep ] || fail "--output overwrote a file"
DISPLAY= expect 0 "no X display \(DISPLAY unset\): writing annotated images instead" "$det" --input "$img" --display
[ -f ssl-detections/ssl3-a3-00.png ] || fail "--display without X wrote no annotated image"
# 15. Integer options are integers in range.
expect 2 "option --window: expected an integer in \[2, 128\], got \"2.5\"" "$det" --input "$img" --window 2.5
expect 2 "option --window: expected an integer in \[2, 128\], got \"4294967298\"" "$det" --input "$img" --window 4294967298
expect 2 "option --threads: expected an integer in \[0, 256\], got \"-1\"" "$det" --input "$img" --threads -1
# Thread counts: never negative (read as a huge unsigned count it would start billions of threads), zero only where
# the tutorial's --help documents it as "all cores".
expect 2 "--nthreads: expected an integer in \[0, 256\], got \"-1\"" "$T/tutorial-ssl-detector-pose" --nthreads -1
for t in -1 0; do
  expect 2 "--threads: expected an integer in \[1, 256\], got \"$t\"" "$T/tutorial-ssl-detector-recall" --threads "$t"
  expect 2 "--threads: expected an integer in \[1, 64\], got \"$t\"" "$T/tutorial-ssl-servo-monte-carlo" --threads "$t"
done
expect 2 "--seed: expected an integer" "$sim" --output s --seed 1e15 --frames 1
expect 2 "option --seed: expected an integer" "$trk" --sequence "$D/sequences/approach-clear" --seed 1e15
# 16. Annotated images that could not be written are not claimed written.
mkdir -p out/ssl3-a3-00.png
expect 1 "0 annotated image\(s\) in out/" "$det" --input "$img" --output out
grep -q "out/ssl3-a3-00.png: cannot write the annotated image" "$work/_stderr" || fail "unwritten annotated image not told"
# 17. A truncated PNG: a clear reason, no leak (LeakSanitizer runs in the sanitizer build).
head -c 1000 "$img" >t.png
expect 1 "t.png: PNG data truncated" "$det" --input t.png
# 18. Clear reasons: 16-bit and ASCII PGM are read, a truncated PGM is named.
printf 'P5\n4 4\n255\nabc' >tr.pgm
expect 1 "tr.pgm: PGM data truncated: 3 bytes of pixels, the header \(4 x 4, maxval 255\) needs 16" "$det" --input tr.pgm
printf 'P2\n2 2\n255\n0 10\n20 255\n' >a.pgm
expect 0 "1 image" "$det" --input a.pgm --output o16
python3 -c "open('s16.pgm','wb').write(b'P5\n2 2\n65535\n'+b'\xff\xff'*4)"
expect 0 "1 image" "$det" --input s16.pgm --output o16

# 5, 14. Camera files with non-finite or absurd intrinsics, width 0; the tracker and the detector.
cam() { sed "s#<$1>[^<]*</$1>#<$1>$2</$1>#" "$D/camera/camera-640x480.xml" >"$3"; }
for v in inf 1e300; do
  cam px "$v" c.xml
  expect 2 "c.xml: camera \"Camera\": px: must be a finite number" "$det" --json --camera c.xml --input "$img"
done
cam u0 nan c.xml
expect 2 "u0: must be a finite number" "$det" --json --camera c.xml --input "$img"
cam px 0 c.xml
expect 2 "c.xml: camera \"Camera\": px: must be > 0, got 0" "$det" --camera c.xml --input "$img"
mkseq() {
  rm -rf "$1"
  mkdir -p "$1/images"
  cp "$D/sequences/approach-clear/camera.xml" "$D/sequences/approach-clear/sequence.json" "$1/"
  head -n 3 "$D/sequences/approach-clear/frames.csv" >"$1/frames.csv"
  cp "$D/sequences/approach-clear/images/000000.png" "$D/sequences/approach-clear/images/000001.png" "$1/images/"
}
for v in inf 1e300; do
  mkseq s1
  sed -i "s#<px>[^<]*</px>#<px>$v</px>#" s1/camera.xml
  expect 1 "px: must be a finite number" "$trk" --sequence s1 --csv s1.csv
done
mkseq s1
sed -i 's#"camera_to_vehicle": \[0.5, 0#"camera_to_vehicle": [0.5, 1e300#' s1/sequence.json
expect 1 "camera_to_vehicle: element 2 is 1e\+300, beyond" "$trk" --sequence s1 --csv s1.csv
expect 2 "camera_to_vehicle: element 2 is 1e\+300, beyond" "$vs" --quiet --output-dir vs1 s1
mkseq s1
printf 'name t\nlandmark A 0 0 0 0.1 0.5\nlandmark B 0.3 0 0 0.1 0.4\n' >s1/t.txt
sed -i 's#"ssl3-a3"#"t.txt"#' s1/sequence.json
expect 1 "s1/t.txt:3: p: 0.4 differs from 0.5" "$trk" --sequence s1 --csv s1.csv
mkseq s1
sed -i 's#<image_width>[^<]*<#<image_width>0<#' s1/camera.xml
rm s1/images/000000.png
printf 'P5\n65536 65536\n255\n' >s1/images/000000.pgm
expect 1 "image_width: must be > 0" "$trk" --sequence s1 --csv s1.csv
# A relative target path in sequence.json is the sequence folder's, in the tracker as in vs-apriltag.
mkseq s1
cp "$D/targets/ssl3-a3.txt" s1/rel.txt
sed -i 's#"ssl3-a3"#"rel.txt"#' s1/sequence.json
expect 0 "2 frame" "$trk" --sequence s1 --csv s1.csv --quiet
expect 0 "" "$vs" --quiet --output-dir vs2 s1

# 4. AprilTag decimation is bounded.
expect 2 "--apriltag-decimate: expected a number in \[1, 16\], got \"240\"" "$vs" --apriltag-decimate 240 s1
# 7. A range of 1e13 m in frames.csv: an input error, not a 6 GB histogram.
mkseq s2
python3 - <<'PY'
import csv
rows = list(csv.reader(open('s2/frames.csv')))
rows[2][rows[0].index('range')] = '1e13'
csv.writer(open('s2/frames.csv', 'w', newline=''), lineterminator='\n').writerows(rows)
PY
expect 2 "s2/frames.csv: frame 1: range: 1e\+13 m, beyond the 1000 m" "$vs" --quiet --output-dir vs3 s2
# 16. Output to a full device is an error.
if [ -w /dev/full ]; then
  expect 1 "/dev/full: write error" "$trk" --sequence "$D/sequences/approach-clear" --csv /dev/full --quiet --max-frames 2
  [ "$(wc -l <"$work/_stderr")" -eq 1 ] || fail "tracker to a full device: expected one line: $(cat "$work/_stderr")"
  timeout 120 "$vs" --quiet --max-frames 2 --output-dir vs4 "$D/sequences/approach-clear" >/dev/full 2>err
  [ $? -eq 1 ] || fail "vs-apriltag to a full device: exit status"
  grep -q "standard output: write error" err || fail "vs-apriltag to a full device: message"
fi

# 8. A camera of 4294967295 or 20000 x 20000 pixels for the simulator.
sed 's#<image_width>640#<image_width>4294967296#' "$D/camera/camera-640x480.xml" >huge.xml
expect 2 "image_width: 4294967296 pixels: a side exceeds the limit of 16384" "$sim" --output s3 --camera huge.xml --frames 1
sed 's#<image_width>640#<image_width>20000#; s#<image_height>480#<image_height>20000#' "$D/camera/camera-640x480.xml" >huge.xml
expect 2 "20000 x 20000 pixels: a side exceeds the limit of 16384" "$sim" --output s3 --camera huge.xml --frames 1
# 9. P = 0.99999999; 11. 20,000 landmarks; 13. a landmark at 1.7e308 m.
printf 'name t\nlandmark A 0 0 0 0.1 0.99999999\n' >p.txt
expect 2 "p.txt:2: p: must be in \[0.2, 0.8\], got 0.99999999" "$sim" --output s4 --target p.txt --frames 1
python3 -c "
print('name t')
for i in range(20000): print('landmark L%d %g 0 0 0.001' % (i, i * 0.003 - 30))" >many.txt
expect 2 "^tutorial-ssl-target-generator: many.txt:66: landmark: more than 64 landmarks" "$gen" --target many.txt --output g
printf 'name t\nlandmark B 1.7e308 0 0 1e308\n' >h.txt
expect 2 "h.txt:2: centre: each coordinate must be within" "$gen" --target h.txt --output g
# 10. A 100 m sheet: bounded layout and a clear PNG size error, nothing written.
printf 'name t\nsheet 100 100 0 0\nlandmark A 0 0 0 0.1\n' >s100.txt
expect 2 "the PNG holds 1 to 32767 px a side" "$gen" --target s100.txt --output g
[ ! -e g.pdf ] || fail "a rejected target wrote g.pdf"
# 17. The simulator's --background image goes through the same checked reader.
expect 2 "vpSSLBackground: cannot read image t.png: t.png: PNG data truncated" "$sim" --output s5 --background t.png --frames 1
# 18. "+-0.1" is not a number.
printf 'name t\nlandmark A +-0.1 0 0 0.1\n' >pm.txt
expect 2 "pm.txt:2: x: not a number: \"\+-0.1\"" "$gen" --target pm.txt --output g

# Nothing a user gave is written over: no output inside a recorded sequence (the input or another one), none onto an
# input file, no annotated image over the image it annotates.
mkseq s6
cp s6/frames.csv frames.keep
expect 2 "^tutorial-ssl-tracker: --csv: s6/frames.csv is inside the recorded sequence .*/s6, which is read, never written" \
  "$trk" --sequence s6 --csv s6/frames.csv --quiet
expect 2 "--output-dir: s6/images is inside the recorded sequence" \
  "$trk" --sequence "$D/sequences/approach-clear" --output-dir s6/images --max-frames 1 --csv z.csv
expect 2 "--output-dir: s6 is inside the recorded sequence" "$vs" --quiet --output-dir s6 s6
expect 2 "--output: s6/images is inside the recorded sequence" "$det" --input s6/images/000000.png --output s6/images
cmp -s s6/frames.csv frames.keep || fail "the sequence's frames.csv was written over"
cmp -s s6/images/000000.png "$D/sequences/approach-clear/images/000000.png" || fail "a sequence image was written over"
[ ! -e z.csv ] || fail "a refused run wrote z.csv"
mkdir -p photos
cp "$img" photos/
expect 2 "--output: photos is the folder of the input images: the annotated images would replace them" \
  "$det" --input photos/ssl3-a3-00.png --output photos
cmp -s photos/ssl3-a3-00.png "$img" || fail "the detector wrote over its input image"
cp "$D/camera/camera-640x480.xml" cam.xml
expect 2 "--csv: cam.xml is the input cam.xml, which is read, never written" \
  "$trk" --sequence s6 --camera cam.xml --csv cam.xml
cmp -s cam.xml "$D/camera/camera-640x480.xml" || fail "the tracker wrote over the camera file"

# 1, 2, 12, 17 in the sequence checker and the recorder: images go through the same checked reader (header size
# before decoding, truncated data named, nothing printed by libpng).
for f in lie big t; do
  mkseq c$f
  cp $f.png c$f/images/000001.png
  expect 1 "" "$chk" c$f
  [ ! -s "$work/_stderr" ] || fail "check-sequence on $f.png: stray stderr: $(cat "$work/_stderr")"
done
grep -q "^ct/frames.csv:3: image: images/000001.png: cannot be read (ct/images/000001.png: PNG data truncated" \
  "$work/_stdout" || fail "check-sequence, truncated PNG: $(cat "$work/_stdout")"
"$chk" clie | grep -q "clie/images/000001.png: PNG header: 65536 x 65537 pixels: a side exceeds the limit" ||
  fail "check-sequence, a PNG header beyond the limits"
"$chk" cbig | grep -q "cbig/images/000001.png: PNG header: 20000 x 20000 pixels" ||
  fail "check-sequence, a 20000 x 20000 PNG header"
for f in lie t; do
  rm -rf rin rout
  mkdir rin
  cp $f.png rin/000000.png
  expect 1 "^tutorial-ssl-record: rin/000000.png: PNG (header: 65536 x 65537 pixels|data truncated)" \
    "$rec" --input rin/%06d.png --camera "$D/camera/camera-640x480.xml" --output rout --rate 10
  [ "$(wc -l <"$work/_stderr")" -eq 1 ] || fail "record on $f.png: expected one line: $(cat "$work/_stderr")"
done
# 18 in the sequence checker: CR-only line ends named; a relative target is the sequence folder's, as in the
# tracker (a valid target of that name in the working folder changes nothing).
mkseq ccr
head -n 3 "$D/sequences/approach-clear/frames.csv" | tr '\n' '\r' >ccr/frames.csv
expect 1 "" "$chk" ccr
grep -q "^ccr/frames.csv:1: line end: a carriage return inside the line" "$work/_stdout" ||
  fail "check-sequence, CR line ends: $(cat "$work/_stdout")"
mkseq crel
printf 'name t\nlandmark A 0 0 0 0.1 0.5\nlandmark B 0.3 0 0 0.1 0.4\n' >crel/rel.txt
sed -i 's#"ssl3-a3"#"rel.txt"#' crel/sequence.json
cp "$D/targets/ssl3-a3.txt" rel.txt
expect 1 "" "$chk" crel
grep -q "crel/rel.txt:3: p: 0.4 differs from 0.5" "$work/_stdout" || fail "check-sequence, relative target: $(cat "$work/_stdout")"

echo "hostile_input: all checks passed"

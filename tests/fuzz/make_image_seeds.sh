#!/usr/bin/env bash
# Writes the EXR and PNG seeds (tests/fuzz/corpus/fuzz_exr_map, fuzz_image_input) with oiiotool: small maps of
# every pixel type and layout the readers meet (FLOAT / HALF / UINT, scanline and tiled, Z alone, RGBA, a depth
# layer), PNG frames (8- and 16-bit, grey, RGBA), plus issue 23's header reproducers. SHADOWLAB=path/to/shadowlab
# adds real maps with passes (cube faces, cascades). Deterministic apart from the tools' own versions.
# Kept as found, not written here: fuzz_exr_map/preview_overflow.exr, the campaign's preview-size overflow (io_exr_test).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
exr=$here/corpus/fuzz_exr_map
img=$here/corpus/fuzz_image_input
mkdir -p "$exr" "$img"
o() { oiiotool -q --nosoftwareattrib "$@"; }
o --pattern fill:top=0.1:bottom=0.9 8x8 1 --chnames Z -d float -o "$exr/z-float.exr"
o --pattern fill:left=0:right=1 8x4 1 --chnames Z -d half -o "$exr/z-half.exr"
o --pattern fill:left=0:right=1 8x4 1 --chnames Z -d uint32 -o "$exr/z-uint.exr"
o --pattern fill:top=0:bottom=1 16x16 1 --chnames Z -d float --tile 8 8 -o "$exr/z-tiled.exr"
o --pattern checker:width=2:height=2 8x8 4 -d half -o "$exr/rgba.exr"
o --pattern constant:color=0.5 4x4 2 --chnames ViewLayer.Depth.Z,ViewLayer.Combined.A -d float -o "$exr/layer.exr"
o --pattern constant:color=0.5 4x4 1 --chnames Z -d float \
  --attrib shadowlab:technique shadowmap --attrib shadowlab:depthFormat d24 --attrib:type=int shadowlab:passCount 0 \
  --attrib:type=matrix worldToCamera "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1" \
  --attrib:type=matrix worldToNDC "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1" -o "$exr/attributes.exr"
o --pattern constant:color=0.5 4x4 1 --chnames Z -d float --attrib:type=int shadowlab:passCount 2 -o "$exr/passes-missing.exr"
o --pattern constant:color=0.5 4x4 1 --chnames Z -d float --compression none -o "$exr/uncompressed.exr"
o --pattern fill:top=0:bottom=1 8x8 3 -d uint8 -o "$img/rgb8.png"
o --pattern fill:top=0:bottom=1 8x8 1 -d uint16 -o "$img/grey16.png"
o --pattern checker:width=2:height=2 8x8 4 -d uint8 -o "$img/rgba8.png"
cp "$exr/z-float.exr" "$exr/z-tiled.exr" "$exr/layer.exr" "$img/"
# Issue 23: a truncated PNG and one with a bad CRC (libpng's stray line, a leak).
head -c 60 "$img/rgb8.png" >"$img/truncated.png"
python3 - "$img/rgb8.png" "$img/bad-crc.png" <<'PY'
import sys
b = bytearray(open(sys.argv[1], "rb").read()); b[29] ^= 0xFF  # inside IHDR's CRC
open(sys.argv[2], "wb").write(bytes(b))
PY
if [ -n "${SHADOWLAB:-}" ]; then
  t=$(mktemp -d)
  for s in tutorial duel point-lights; do
    "$SHADOWLAB" render "$s" --size 16x16 --shadow-size 16 --out "$t/$s.png" --maps "$t/maps-$s" >/dev/null 2>&1 || true
  done
  for f in "$t"/maps-*/*.exr; do [ -f "$f" ] && [ "$(stat -c %s "$f")" -lt 20000 ] && cp "$f" "$exr/$(basename "$(dirname "$f")")-$(basename "$f")"; done
  rm -rf "$t"
fi

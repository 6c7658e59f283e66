#!/usr/bin/env bash
# cg's OpenEXR files read by OpenEXR's own tools (Debian package openexr):
# exrheader sees the channels, types and compression cg writes, and
# exrmaketiled (the C++ library) rewrites them as tiled and mipmapped files
# that cg reads back to the same pixels.
# usage: test_image_exr_tools.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
for tool in exrheader exrmaketiled; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool missing (Debian package openexr)"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# A 40 x 20 PFM of values a half holds exactly (k/8 for k < 256), via awk.
awk 'BEGIN { printf "PF\n40 20\n-1.0\n" }' > in.pfm
awk 'BEGIN { for (i = 0; i < 40 * 20 * 3; i++) print (i * 7) % 256 / 8 }' \
  | perl -ne 'print pack("f<", $_)' >> in.pfm
"$cg" convert in.pfm half.exr || { echo "FAIL: cg cannot write EXR"; exit 1; }
header=$(exrheader half.exr) || fail "exrheader refused cg's file"
for want in "A, 16-bit floating-point" "B, 16-bit floating-point" "G, 16-bit floating-point" \
            "R, 16-bit floating-point" "compression (type compression): zip" \
            "dataWindow (type box2i): (0 0) - (39 19)"; do
  grep -qF "$want" <<<"$header" || fail "exrheader lacks '$want': $header"
done
"$cg" convert in.pfm float.exr --exr-float
grep -qF "R, 32-bit floating-point" <<<"$(exrheader float.exr)" || fail "--exr-float not float"

for flags in "-t 16 16" "-t 7 5 -m" "-t 64 64 -z piz"; do
  rm -f tiled.exr back.pfm
  # shellcheck disable=SC2086
  exrmaketiled $flags half.exr tiled.exr >/dev/null || { fail "exrmaketiled $flags"; continue; }
  grep -q "tiledimage" <<<"$(exrheader tiled.exr)" || fail "exrmaketiled $flags made no tiles"
  "$cg" convert tiled.exr back.pfm && cmp -s in.pfm back.pfm \
    || fail "tiled EXR ($flags) read back different from the source"
done
exit $failed

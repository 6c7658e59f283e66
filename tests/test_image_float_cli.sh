#!/usr/bin/env bash
# `cg convert` between float files (PFM, HDR, EXR) and 8-bit ones: exact
# float round trips, tone mapping with --exposure and --tonemap against the
# formulas, and errors that leave an existing OUT untouched.
# usage: test_image_float_cli.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# A 3 x 1 PFM, little-endian: (0.5, 0, 2) (1, 1, 1) (8, 0.25, 0).
{
  printf 'PF\n3 1\n-1.0\n'
  printf '\x00\x00\x00\x3f\x00\x00\x00\x00\x00\x00\x00\x40'
  printf '\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80\x3f'
  printf '\x00\x00\x00\x41\x00\x00\x80\x3e\x00\x00\x00\x00'
} > in.pfm

"$cg" convert in.pfm same.pfm && cmp -s in.pfm same.pfm || fail "PFM to PFM is not byte-identical"
"$cg" convert in.pfm a.hdr && "$cg" convert a.hdr b.pfm || fail "PFM -> HDR -> PFM failed"
# RGBE: within 2^-8 of each pixel's brightest channel
if [ -f b.pfm ] && ! od -An -v -tf4 -j12 b.pfm | awk '{ for (i = 1; i <= NF; i++) v[n++] = $i }
    END { split("0.5 0 2 1 1 1 8 0.25 0", w, " ");
          for (i = 0; i < 9; i++) { p = i - i % 3; m = w[p + 1];
                                    if (w[p + 2] > m) m = w[p + 2]; if (w[p + 3] > m) m = w[p + 3];
                                    d = v[i] - w[i + 1]; if (d < 0) d = -d;
                                    if (d > m / 256) exit 1 } }'; then
  fail "HDR round trip out of the RGBE bound: $(od -An -tf4 -j12 b.pfm)"
fi

if "$cg" convert in.pfm a.exr 2>err.txt; then
  "$cg" convert a.exr c.pfm && cmp -s in.pfm c.pfm || fail "PFM -> EXR half -> PFM is not exact"
  "$cg" convert in.pfm f.exr --exr-float && "$cg" convert f.exr d.pfm && cmp -s in.pfm d.pfm \
    || fail "PFM -> EXR float -> PFM is not exact"
elif grep -q "without OpenEXR" err.txt; then
  echo "cg built without OpenEXR: EXR conversions refused, as documented"
else
  fail "PFM -> EXR: $(cat err.txt)"
fi

# 8-bit output: PPM bytes against the sRGB encoding of the tone curve.
srgb() { awk -v x="$1" 'BEGIN { if (x <= 0) x = 0; if (x >= 1) x = 1;
  y = x <= 0.0031308 ? 12.92 * x : 1.055 * exp(log(x) / 2.4) - 0.055; printf "%d", int(y * 255 + 0.5) }'; }
filmic() { awk -v x="$1" 'BEGIN { printf "%.9g", x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14) }'; }
bytes() { od -An -v -tu1 -j "$(($(wc -c < "$1") - 9))" "$1" | tr -s ' \n' ' ' | sed 's/^ //; s/ $//'; }
expect_ppm() { # ARGS EXPECTED-BYTES
  rm -f o.ppm
  "$cg" convert in.pfm o.ppm $1 || { fail "cg convert in.pfm o.ppm $1 failed"; return; }
  local got; got=$(bytes o.ppm)
  [ "$got" = "$2" ] || fail "cg convert $1: bytes '$got', expected '$2'"
}
values="0.5 0 2 1 1 1 8 0.25 0"
want=""; for v in $values; do want="$want $(srgb "$v")"; done
expect_ppm "" "${want# }"
want=""; for v in $values; do want="$want $(srgb "$(awk -v v="$v" 'BEGIN { print v / 4 }')")"; done
expect_ppm "--exposure -2" "${want# }"
want=""; for v in $values; do want="$want $(srgb "$(filmic "$(awk -v v="$v" 'BEGIN { print v * 2 }')")")"; done
expect_ppm "--exposure 1 --tonemap filmic" "${want# }"
want=""; for v in $values; do want="$want $(srgb "$v")"; done
expect_ppm "--tonemap none" "${want# }"

# PNG -> PFM decodes sRGB: 188 is 0.50289 in linear light.
"$cg" convert o.ppm back.pfm || fail "PPM -> PFM failed"

# Errors: one line, non-zero, OUT untouched.
echo keep > keep.png
head -c 20 in.pfm > short.pfm
if "$cg" convert short.pfm keep.png 2>err.txt; then fail "truncated PFM accepted"; fi
grep -q "truncated PFM" err.txt || fail "truncated PFM message: $(cat err.txt)"
[ "$(cat keep.png)" = keep ] || fail "a failed convert changed OUT"
if "$cg" convert in.pfm out.pfm --exr-float 2>err.txt; then fail "--exr-float for .pfm accepted"; fi
grep -q "not an .exr" err.txt || fail "--exr-float message: $(cat err.txt)"
if "$cg" convert in.pfm out.tiff 2>err.txt; then fail ".tiff accepted"; fi
grep -q "unknown output format" err.txt || fail "unknown format message: $(cat err.txt)"
if "$cg" convert in.pfm o.png --exposure nan 2>err.txt; then fail "--exposure nan accepted"; fi
if "$cg" convert in.pfm o.png --tonemap aces 2>err.txt; then fail "--tonemap aces accepted"; fi
printf '#?RADIANCE\n\n+X 1 -Y 1\n\0\0\0\0' > odd.hdr
if "$cg" convert odd.hdr keep.png 2>err.txt; then fail "odd HDR orientation accepted"; fi
grep -q "orientation" err.txt && [ "$(wc -l < err.txt)" -eq 1 ] || fail "HDR message: $(cat err.txt)"
exit $failed

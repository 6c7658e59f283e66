#!/usr/bin/env bash
# The `cg color FROM-TO V1 V2 V3 [V4]` contract: values, spelling, errors.
# usage: test_color.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
failed=0

# expect "ARGS" "EXPECTED VALUES" [TOLERANCE]: every printed value within tolerance.
expect() {
  local out
  out=$("$cg" color $1 2>&1) || { echo "FAIL: cg color $1 exited non-zero: $out"; failed=1; return; }
  if ! awk -v got="$out" -v want="$2" -v tol="${3:-1e-12}" 'BEGIN {
      n = split(got, g, " "); m = split(want, w, " ");
      if (n != m) exit 1;
      for (i = 1; i <= n; i++) { d = g[i] - w[i]; if (d < 0) d = -d; if (d > tol) exit 1 }
      exit 0 }'; then
    echo "FAIL: cg color $1 printed '$out', expected '$2'"
    failed=1
  fi
}

# expect_error "ARGS" "TEXT IN MESSAGE"
expect_error() {
  local out status
  out=$("$cg" color $1 2>&1)
  status=$?
  if [ $status -eq 0 ] || ! grep -q -- "$2" <<<"$out"; then
    echo "FAIL: cg color $1 should fail naming '$2' (status $status): $out"
    failed=1
  fi
}

expect "rgb-hsv 1 0 0" "0 1 1"
expect "rgb-hsv 0 0 1" "240 1 1"
expect "rgb-hsv 1 0.5 0" "30 1 1"
expect "rgb-hsl 0.2 0.4 0.3" "150 0.33333333333333333 0.3"
expect "hsv-rgb 300 1 1" "1 0 1"
expect "hsl-rgb 120 1 0.25" "0 0.5 0"
expect "hsv-rgb 420 1 1" "1 1 0"
expect "rgb-cmy 1 0.25 0" "0 0.75 1"
expect "rgb-cmyk 0.5 0.25 0" "0 0.5 1 0.5"
expect "cmyk-rgb 0 0.5 1 0.5" "0.5 0.25 0"
expect "rgb-yiq 1 1 1" "1 0 0"
expect "rgb-ycbcr601 1 0 0" "0.299 -0.16873589164785552 0.5"
expect "rgb-ycbcr709 1 1 1" "1 0 0"
expect "ycbcr709-rgb 1 0 0" "1 1 1"
expect "rgb-xyz 1 1 1" "0.9505 1 1.089"
expect "rgb-lab 1 1 1" "100 0 0"
expect "lab-rgb 100 0 0" "1 1 1"
expect "xyz-lab 0.9505 1 1.089" "100 0 0"
expect "srgb-linear 0.5 0.5 0.5" "0.21404114048223255 0.21404114048223255 0.21404114048223255"
expect "linear-srgb 0.21404114048223255 1 0" "0.5 1 0"
expect "srgb-linear 0.04045 0 1" "0.0031308049535603713 0 1"
expect "rgb-rgb 0.1 0.2 0.3" "0.1 0.2 0.3"
expect "rgb-hsv #ff8000" "30.117647058823529 1 1"
expect "rgb-rgb cornflowerblue" "0.39215686274509803 0.58431372549019611 0.92941176470588238"
# Out of range input is clamped; hue is reduced modulo 360.
expect "rgb-hsv 2 -1 0" "0 1 1"
expect "hsv-rgb -60 1 1" "1 0 1"

# Full precision: 17 significant digits.
out=$("$cg" color rgb-hsl 0.2 0.4 0.3)
if ! grep -q "0.33333333333333331" <<<"$out"; then
  echo "FAIL: rgb-hsl output not printed with %.17g: $out"
  failed=1
fi

expect_error "rgb-hsv 1 2" "takes 3 values"
expect_error "cmyk-rgb 1 2 3" "takes 4 values"
expect_error "rgb-hsv 1 nan 0" "nan"
expect_error "rgb-hsv 1 inf 0" "inf"
expect_error "rgb-hsv 1 0x 0" "0x"
expect_error "rgb-hsb 1 0 0" "rgb-hsb"
expect_error "rgbhsv 1 0 0" "rgbhsv"
expect_error "rgb-hsv #12345" "#12345"
expect_error "rgb-hsv bluish" "bluish"
expect_error "" "expected FROM-TO"

exit $failed

#!/bin/bash
# cg svg as a user meets it: the output's size from --width, --height and
# --zoom, --background, pixels read back from binary PPM, one warning per
# kind of skipped content, every bad input refused with a message and no
# output written; and cg draw's compositing command.
set -u
CG=$1
BUILD=$3
dir=$(mktemp -d "${BUILD:-/tmp}/cg_svg_test.XXXXXX")
trap 'rm -rf "$dir"' EXIT
fail=0
ok() { echo "FAIL: $*"; fail=1; }

# Pixel bytes of a binary PPM (the last N bytes) and its header.
pixels() { tail -c "$2" "$1" | od -An -tu1 -v | tr -s ' \n' ' ' | sed 's/^ //; s/ $//'; }
header() { head -c 20 "$1" | tr '\n' ' ' | cut -d' ' -f1-4; }

# expect_fail STATUS "TEXT" ARGS...: exits with STATUS naming TEXT, writes no output.
expect_fail() {
  local want="$1" text="$2" out status
  shift 2
  rm -f "$dir/bad.png"
  out=$("$CG" svg "$@" 2>&1)
  status=$?
  [ "$status" = "$want" ] || ok "cg svg $* exited $status, expected $want: $out"
  grep -qF -- "$text" <<<"$out" || ok "cg svg $* should say '$text': $out"
  [ ! -e "$dir/bad.png" ] || ok "cg svg $* left an output file"
}

# 4 x 2: a red square on the left, half-opaque blue on the right.
cat > "$dir/two.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" width="4" height="2">
  <rect width="2" height="2" fill="#ff0000"/>
  <rect x="2" width="2" height="2" fill="blue" opacity="0.5"/>
</svg>
SVG
"$CG" svg "$dir/two.svg" -o "$dir/two.ppm" --background white || ok "two.svg failed"
[ "$(header "$dir/two.ppm")" = "P6 4 2 255" ] || ok "two.ppm header: $(header "$dir/two.ppm")"
# blue at half opacity over white, mixed in sRGB: 127.5 (127 or 128, as
# the paint's alpha is a byte), not linear light's 188
grep -Eq '^255 0 0 255 0 0 (127 127|128 128) 255 (127 127|128 128) 255$' <<<"$(pixels "$dir/two.ppm" 12)" ||
  ok "two.ppm pixels: $(pixels "$dir/two.ppm" 12)"
"$CG" svg "$dir/two.svg" -o "$dir/w.ppm" --width 8 || ok "--width failed"
[ "$(header "$dir/w.ppm")" = "P6 8 4 255" ] || ok "--width 8 gave $(header "$dir/w.ppm")"
"$CG" svg "$dir/two.svg" -o "$dir/h.ppm" --height=6 || ok "--height failed"
[ "$(header "$dir/h.ppm")" = "P6 12 6 255" ] || ok "--height 6 gave $(header "$dir/h.ppm")"
"$CG" svg "$dir/two.svg" -o "$dir/z.ppm" --zoom 2.5 || ok "--zoom failed"
[ "$(header "$dir/z.ppm")" = "P6 10 5 255" ] || ok "--zoom 2.5 gave $(header "$dir/z.ppm")"
"$CG" svg "$dir/two.svg" -o "$dir/two.png" || ok "PNG output failed"
[ "$(head -c 4 "$dir/two.png" | od -An -c | tr -d ' ')" = "211PNG" ] || ok "two.png is not a PNG"

# skipped content: one warning per kind, the rest drawn
cat > "$dir/skip.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" width="2" height="1">
  <filter id="f"/><filter id="g"/><text><textPath>a</textPath></text><text><textPath>b</textPath></text>
  <rect width="2" height="1" fill="lime" filter="url(#f)"/>
</svg>
SVG
err=$("$CG" svg "$dir/skip.svg" -o "$dir/skip.ppm" 2>&1) || ok "skip.svg failed: $err"
[ "$(grep -c 'warning: skipped <filter>' <<<"$err")" = 1 ] || ok "filter warnings: $err"
[ "$(grep -c 'warning: skipped <textPath>' <<<"$err")" = 1 ] || ok "text warnings: $err"
grep -q "filter effects are not supported: drawn without them" <<<"$err" || ok "no filter-use warning: $err"
[ "$(pixels "$dir/skip.ppm" 6)" = "0 255 0 0 255 0" ] || ok "skip.ppm: $(pixels "$dir/skip.ppm" 6)"

# bad usage (status 2) and bad files (status 1)
expect_fail 2 "expected -o OUT.png" "$dir/two.svg"
expect_fail 2 "expected an input file" -o "$dir/bad.png"
expect_fail 2 "give one of --width, --height and --zoom" "$dir/two.svg" -o "$dir/bad.png" --width 4 --zoom 2
expect_fail 2 "--zoom: expected a number > 0" "$dir/two.svg" -o "$dir/bad.png" --zoom 0
expect_fail 2 "--width" "$dir/two.svg" -o "$dir/bad.png" --width abc
expect_fail 2 "unknown option '--dpi'" "$dir/two.svg" -o "$dir/bad.png" --dpi 96
expect_fail 2 "--background" "$dir/two.svg" -o "$dir/bad.png" --background nocolour
expect_fail 2 "unknown output format" "$dir/two.svg" -o "$dir/bad.gif"
expect_fail 1 "$dir/none.svg: cannot open" "$dir/none.svg" -o "$dir/bad.png"
printf '<svg xmlns="http://www.w3.org/2000/svg">\n<g>\n</svg>\n' > "$dir/broken.svg"
expect_fail 1 "broken.svg:3: malformed XML: mismatched tag" "$dir/broken.svg" -o "$dir/bad.png"
printf '<!DOCTYPE svg [<!ENTITY a "x">]>\n<svg>&a;</svg>\n' > "$dir/entity.svg"
expect_fail 1 "entity declaration 'a' refused" "$dir/entity.svg" -o "$dir/bad.png"
printf '<svg xmlns="http://www.w3.org/2000/svg" width="1e9" height="1e9"/>\n' > "$dir/huge.svg"
expect_fail 1 "over the limit" "$dir/huge.svg" -o "$dir/bad.png"
# a use cycle: refused, and an existing output is left as it was
printf '<svg xmlns="http://www.w3.org/2000/svg"><use id="a" href="#b"/><use id="b" href="#a"/></svg>\n' > "$dir/cycle.svg"
cp "$dir/two.png" "$dir/keep.png"
out=$("$CG" svg "$dir/cycle.svg" -o "$dir/keep.png" 2>&1) && ok "a use cycle was drawn"
grep -q "cycle" <<<"$out" || ok "use cycle message: $out"
cmp -s "$dir/two.png" "$dir/keep.png" || ok "a failed cg svg changed its output file"
"$CG" help svg | grep -qF "usage: cg svg IN.svg -o OUT.png [--width W | --height H | --zoom Z] [--background COLOR]" ||
  ok "cg help svg: wrong usage line"

# cg draw: compositing in linear light (the default: 188) or sRGB (128)
cat > "$dir/mix.draw" <<'SCRIPT'
size 3 1
background black
color white
aapolygon 0 0 0.5 0 0.5 1 0 1
compositing srgb
aapolygon 1 0 1.5 0 1.5 1 1 1
compositing srgb over multiply
color #808080
aapolygon 2 0 3 0 3 1 2 1
SCRIPT
"$CG" draw "$dir/mix.draw" -o "$dir/mix.ppm" || ok "compositing script failed"
[ "$(pixels "$dir/mix.ppm" 9)" = "188 188 188 128 128 128 0 0 0" ] ||
  ok "compositing pixels: $(pixels "$dir/mix.ppm" 9)"
printf 'size 2 2\ncompositing cmyk\n' > "$dir/bad.draw"
out=$("$CG" draw "$dir/bad.draw" -o "$dir/bad.ppm" 2>&1) && ok "compositing cmyk accepted"
grep -q "bad.draw:2: expected linear or srgb after 'compositing', got 'cmyk'" <<<"$out" ||
  ok "compositing error: $out"
printf 'size 2 2\ncompositing srgb sideways\n' > "$dir/bad.draw"
out=$("$CG" draw "$dir/bad.draw" -o "$dir/bad.ppm" 2>&1) && ok "operator sideways accepted"
grep -q "bad.draw:2: expected an operator" <<<"$out" || ok "operator error: $out"

[ $fail = 0 ] && echo "test_svg_cli: all checks passed"
exit $fail

#!/usr/bin/env bash
# SVG text and tspan (docs/svg.md, "Text"): the drawings of
# tests/data/svg_text/*.svg by cg against resvg, which is given only the
# fonts of fonts-dejavu-core and fonts-noto-core: cg's mean difference (tests/
# svg_compare.c --pair) is at most 0.75/255 over the whole image and
# 6/255 over the pixels either touches; rsvg-convert's is printed beside.
# Then the layout by its definition: text-anchor end and middle move a run
# by exactly its measured advance, a font-family list skips a family that
# is not installed, tspans inherit, per-character positions, warnings.
# usage: test_svg_text.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1" source_dir=$(cd "$2" && pwd) build_dir="$3"
. "$source_dir/tests/cli_checks.sh"
fonts=/usr/share/fonts/truetype/dejavu noto=/usr/share/fonts/truetype/noto
[ -f "$fonts/DejaVuSans.ttf" ] || { echo "test_svg_text: $fonts not found: skipped (apt-get install fonts-dejavu-core)"; exit 77; }
[ -f "$noto/NotoSansArabic-Regular.ttf" ] || { echo "test_svg_text: $noto not found: skipped (apt-get install fonts-noto-core)"; exit 77; }
compare="$build_dir/tests/svg_compare" ref="$build_dir/tests/text_reference"
[ -x "$compare" ] && [ -x "$ref" ] || { echo "test_svg_text: $compare or $ref not built"; exit 1; }

svg() { # svg NAME: the SVG on stdin -> $work/NAME.svg, drawn as $work/NAME.png
  cat > "$work/$1.svg"
  "$cg" svg "$work/$1.svg" -o "$work/$1.png" 2>"$work/err"
}
same() { # same A B DESCRIPTION: two drawings byte for byte equal
  if cmp -s "$work/$1.png" "$work/$2.png"; then pass; else fail "$3"; fi
}

# 1. Against resvg.
module=""
for dir in "$source_dir/tests/svg/node_modules" "$(npm root -g 2>/dev/null)"; do
  [ -n "$dir" ] && [ -d "$dir/@resvg/resvg-js" ] && module="$dir/@resvg/resvg-js" && break
done
if [ -z "$module" ] || ! command -v node >/dev/null; then
  echo "test_svg_text: node or the npm package @resvg/resvg-js not found: the comparison with resvg is skipped (make test installs it)"
else
  mkdir -p "$work/cg" "$work/resvg" "$work/rsvg"
  ls "$source_dir"/tests/data/svg_text/*.svg > "$work/list"
  CG_RESVG_MODULE="$module" CG_RESVG_FONT_DIR="$fonts:$noto" \
    node "$source_dir/tests/svg/resvg_render.js" 240 "$work/resvg" "$work/list" 2>"$work/err" ||
    fail "resvg: $(cat "$work/err")"
  i=0
  while read -r file; do
    name=$(basename "$file" .svg)
    if "$cg" svg "$file" -o "$work/cg/$i.png" 2>"$work/err"; then pass; else fail "$name: $(cat "$work/err")"; fi
    [ -s "$work/err" ] && fail "$name: cg svg warned: $(cat "$work/err")"
    rsvg=""
    command -v rsvg-convert >/dev/null && rsvg-convert "$file" -o "$work/rsvg/$i.png" 2>/dev/null &&
      rsvg=$("$compare" --pair "$work/rsvg/$i.png" "$work/resvg/$i.png")
    got=$("$compare" --pair "$work/cg/$i.png" "$work/resvg/$i.png") || fail "$name: cannot compare"
    echo "test_svg_text: $name: cg $got; rsvg-convert ${rsvg:-not run}"
    read -r _ mean _ touched _ <<< "$got"
    if awk -v m="$mean" -v t="$touched" 'BEGIN { exit !(m <= 0.75 && t <= 6) }'; then pass; else
      fail "$name: cg differs from resvg by $mean/255 (whole) and $touched/255 (touched), over 0.75 and 6"
    fi
    i=$((i + 1))
  done < "$work/list"
fi

# 2. text-anchor moves the run by its measured advance: end and middle at
# X equal start at X - w and X - w / 2 (byte for byte).
for size in 11 17.5 30; do
  for text in "Anchored" "AV Wa ffi" "x"; do
    w=$("$ref" measure "$fonts/DejaVuSans.ttf" "$size" "$text")
    for anchor in middle end; do
      shifted=$(awk -v w="$w" -v a=$anchor 'BEGIN { printf "%.17g", a == "end" ? 150 - w : 150 - w / 2 }')
      svg anchored <<EOT
<svg xmlns="http://www.w3.org/2000/svg" width="300" height="60"><text x="150" y="40"
 font-family="DejaVu Sans" font-size="$size" text-anchor="$anchor">$text</text></svg>
EOT
      svg start <<EOT
<svg xmlns="http://www.w3.org/2000/svg" width="300" height="60"><text x="$shifted" y="40"
 font-family="DejaVu Sans" font-size="$size">$text</text></svg>
EOT
      same anchored start "text-anchor $anchor of '$text' at $size px is not the start run moved by $w"
    done
  done
done
svg start0 <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="300" height="60"><text x="150" y="40" font-family="DejaVu Sans">Anchored</text></svg>
EOT
svg end0 <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="300" height="60"><text x="150" y="40" font-family="DejaVu Sans" text-anchor="end">Anchored</text></svg>
EOT
cmp -s "$work/start0.png" "$work/end0.png" && fail "text-anchor end draws the start run" || pass

# 3. Fonts: a list skips families that are not installed; weight and style
# choose the face; the group's font reaches the tspan.
svg list <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><text x="5" y="30" font-size="20"
 font-family="'No Such Family Cg', &quot;Another Missing&quot;, DejaVu Serif, sans-serif">Listed</text></svg>
EOT
svg serif <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><text x="5" y="30" font-size="20" font-family="DejaVu Serif">Listed</text></svg>
EOT
same list serif "font-family skipping missing families is not DejaVu Serif"
svg bold <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><text x="5" y="30" font-size="20" font-family="DejaVu Serif" font-weight="bold">Listed</text></svg>
EOT
cmp -s "$work/bold.png" "$work/serif.png" && fail "font-weight bold draws the regular face" || pass
svg italic <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><text x="5" y="30" font-size="20" font-family="DejaVu Serif" font-style="italic">Listed</text></svg>
EOT
cmp -s "$work/italic.png" "$work/serif.png" && fail "font-style italic draws the upright face" || pass
svg inherited <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><g font-family="DejaVu Serif" font-size="10"><text x="5" y="30"><tspan font-size="200%">Listed</tspan></text></g></svg>
EOT
same inherited serif "a tspan's font does not come from its group (font-size 200% of 10)"
# the font shorthand sets style, weight, size and family (line height ignored)
svg shorthand <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><text x="5" y="30" style="font: italic bold 20px/1.5 'DejaVu Serif', serif">Listed</text></svg>
EOT
svg longhand <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><text x="5" y="30" font-style="italic" font-weight="bold" font-size="20" font-family="DejaVu Serif">Listed</text></svg>
EOT
same shorthand longhand "the font shorthand is not its four properties"
svg reset <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><style>text { font: 20px DejaVu Serif }</style><g font-weight="bold" font-style="italic"><text x="5" y="30">Listed</text></g></svg>
EOT
same reset serif "the font shorthand does not reset weight and style to normal"
# a gradient in objectBoundingBox units spans the whole text, across tspans
grad='<defs><linearGradient id="g"><stop offset="0" stop-color="red"/><stop offset="1" stop-color="blue"/></linearGradient></defs>'
svg whole <<EOT
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40">$grad<text x="5" y="30" font-family="DejaVu Sans" font-size="24" fill="url(#g)">abcdef</text></svg>
EOT
svg spans <<EOT
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40">$grad<text x="5" y="30" font-family="DejaVu Sans" font-size="24" fill="url(#g)">ab<tspan>cd</tspan>ef</text></svg>
EOT
same whole spans "a gradient restarts at each tspan instead of spanning the text"
# a tspan's own x starts where the characters would have been put anyway
svg split <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><text x="5 60" y="30" font-family="DejaVu Sans" font-size="20">ab</text></svg>
EOT
svg placed <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="40"><text x="5" y="30" font-family="DejaVu Sans" font-size="20">a<tspan x="60">b</tspan></text></svg>
EOT
same split placed "x=\"5 60\" is not the same as a tspan with x=60 for the second character"

# 4. Warnings and bad input: text draws without a warning; textPath is
# skipped with one; empty and huge texts are fine.
svg plain <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="50" height="20"><text y="15">t</text><text/><text y="10">   </text></svg>
EOT
[ $? = 0 ] && [ ! -s "$work/err" ] && pass || fail "plain text: $(cat "$work/err")"
svg path <<'EOT'
<svg xmlns="http://www.w3.org/2000/svg" width="50" height="20"><path id="p" d="M0 10H50"/><text><textPath href="#p">on a path</textPath></text></svg>
EOT
grep -q "skipped <textPath>: text on a path is not supported" "$work/err" && pass || fail "textPath: '$(cat "$work/err")'"
{
  printf '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="20"><text y="15" x="'
  seq -s ' ' 1 20000
  printf '" font-family="DejaVu Sans">'
  head -c 20000 /dev/zero | tr '\0' 'a'
  printf '</text></svg>'
} | svg many
[ $? = 0 ] && pass || fail "20,000 positioned characters: $(cat "$work/err")"
{
  printf '<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><text>'
  head -c 1000001 /dev/zero | tr '\0' 'a'
  printf '</text></svg>'
} | svg huge
[ $? = 1 ] && grep -q "a <text> element of more than 1000000 characters" "$work/err" && pass ||
  fail "1,000,001 characters: '$(cat "$work/err")'"
finish

#!/usr/bin/env bash
# The text commands of `cg draw` (docs/draw-script.md, "Text"): the pixels
# of `text` are those of the library's own paragraph fill (tests/
# text_reference.c) over random positions, sizes, alignments, baselines and
# widths; `align middle` and `align end` move the run by exactly half and
# all of its measured advance; `wrap` breaks where the greedy definition
# does; quoted strings; bad fonts and bad lines refused with their line.
# Usage: test_draw_text.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
build="$3"
. "$src/tests/cli_checks.sh"
ref="$build/tests/text_reference"
sans=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
serif=/usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf
for f in "$sans" "$serif"; do
  if [ ! -f "$f" ]; then
    echo "test_draw_text: $f not found: skipped (apt-get install fonts-dejavu-core)"
    exit 77
  fi
done
RANDOM=${CG_TEST_SEED:-21} # the same cases on every run (CG_TEST_SEED: others)

draw() { # draw NAME: script on stdin -> $work/NAME.ppm
  "$cg" draw - -o "$work/$1.ppm" 2>"$work/err"
}
same() { # same A B DESCRIPTION: the two images are byte for byte equal
  if cmp -s "$work/$1.ppm" "$work/$2.ppm"; then pass; else fail "$3"; fi
}
close() { # close A B DESCRIPTION: equal but for a few rounding steps (every byte within 1)
  local worst
  worst=$(cmp -l "$work/$1.ppm" "$work/$2.ppm" 2>/dev/null | awk '
    function oct(s,  n, i) { n = 0; for (i = 1; i <= length(s); i++) n = n * 8 + substr(s, i, 1); return n }
    { d = oct($2) - oct($3); if (d < 0) d = -d; if (d > m) m = d } END { print m + 0 }')
  if [ -s "$work/$1.ppm" ] && [ "$(wc -c < "$work/$1.ppm")" = "$(wc -c < "$work/$2.ppm")" ] &&
     [ "$worst" -le 1 ]; then pass; else fail "$3 (a byte differs by $worst)"; fi
}
inked() { # inked NAME: some pixel is not white
  od -An -tu1 -v -j15 "$work/$1.ppm" | tr -s ' ' '\n' | grep -qv '^255$\|^$'
}

words=(The quick brown fox jumps over a lazy dog AV To Wa ffi flow
       Quartz glyph kerning wraps lines at the width Hamburgefonstiv)
aligns=(start middle end)
baselines=(alphabetic top middle bottom)
phrase() { # phrase N: N random words joined by single spaces, into $text
  # (not a command substitution: a subshell would draw other random numbers)
  local i
  text=""
  for ((i = 0; i < $1; i++)); do text+="${text:+ }${words[RANDOM % ${#words[@]}]}"; done
}

# 1. The pixels of `text` are the library's paragraph fill, over 40 cases.
for ((c = 0; c < 40; c++)); do
  font=$([ $((c % 2)) = 0 ] && echo "$sans" || echo "$serif")
  size=$((8 + RANDOM % 60)).$((RANDOM % 100))
  x=$((RANDOM % 300)).$((RANDOM % 1000)) y=$((RANDOM % 200)).$((RANDOM % 1000))
  align=${aligns[RANDOM % 3]} baseline=${baselines[RANDOM % 4]}
  width=$([ $((c % 3)) = 0 ] && echo 0 || echo $((50 + RANDOM % 250)))
  spacing=1.$((RANDOM % 10))
  phrase $((1 + RANDOM % 8))
  "$ref" render "$work/ref.ppm" 320 240 "$font" "$size" "$x" "$y" "$align" "$baseline" \
    "$width" "$spacing" "$text" || fail "text_reference render failed (case $c)"
  draw got <<SCRIPT || fail "case $c: $(cat "$work/err")"
size 320 240
font $font $size
align $align
baseline $baseline
wrap $width
linespacing $spacing
text $x $y $text
SCRIPT
  same got ref "case $c ($font $size px at $x $y, $align, $baseline, wrap $width): pixels differ from the library's fill"
done
inked got && pass || fail "the last case drew nothing"

# 2. Alignment moves the run by exactly its measured advance: `align end`
# at X and `align middle` at X equal `align start` at X - w and X - w / 2.
for ((c = 0; c < 10; c++)); do
  size=$((10 + RANDOM % 40)) x=$((150 + RANDOM % 20)).25
  phrase $((1 + RANDOM % 4))
  w=$("$ref" measure "$sans" "$size" "$text")
  for align in middle end; do
    shifted=$(awk -v x="$x" -v w="$w" -v a="$align" \
      'BEGIN { printf "%.17g", a == "end" ? x - w : x - w / 2 }')
    draw aligned <<SCRIPT || fail "align $align: $(cat "$work/err")"
size 320 80
font $sans $size
align $align
text $x 50 $text
SCRIPT
    draw start <<SCRIPT || fail "align start: $(cat "$work/err")"
size 320 80
font $sans $size
text $shifted 50 $text
SCRIPT
    same aligned start "align $align of '$text' at $size px is not the start run moved by the advance $w"
  done
done
# and a start run is not the end run: the check can tell them apart
draw start0 <<SCRIPT
size 320 80
font $sans 20
text 150 50 kerning
SCRIPT
draw end0 <<SCRIPT
size 320 80
font $sans 20
align end
text 150 50 kerning
SCRIPT
cmp -s "$work/start0.ppm" "$work/end0.ppm" && fail "align end draws the start run" || pass

# 3. Wrapping: `wrap W` gives the lines of the greedy definition (each line
# takes the next word while its measured width stays within W), drawn as
# separate runs one line spacing apart.
for ((c = 0; c < 15; c++)); do
  size=$((10 + RANDOM % 14)) width=$((60 + RANDOM % 200))
  phrase $((4 + RANDOM % 10))
  mapfile -t lines < <("$ref" breaks "$serif" "$size" "$width" "$text")
  [ "${#lines[@]}" -ge 1 ] || fail "no lines for '$text'"
  {
    echo "size 320 400"
    echo "font $serif $size"
    echo "wrap $width"
    echo "linespacing 1.5"
    echo "text 5 20 $text"
  } | draw wrapped || fail "wrap: $(cat "$work/err")"
  {
    echo "size 320 400"
    echo "font $serif $size"
    for ((i = 0; i < ${#lines[@]}; i++)); do
      echo "text 5 $(awk -v i=$i -v s=$size 'BEGIN { printf "%.17g", 20 + i * 1.5 * s }') ${lines[i]}"
    done
  } | draw lines || fail "lines: $(cat "$work/err")"
  # one fill of all the lines against one fill per line: the same coverage
  # but for the rounding of the accumulated areas
  close wrapped lines "wrap $width at $size px: '$text' does not break as ${#lines[@]} greedy lines"
  for line in "${lines[@]}"; do # each line fits, or is a single word
    w=$("$ref" measure "$serif" "$size" "$line")
    if awk -v w="$w" -v W="$width" 'BEGIN { exit !(w <= W) }' || [ "${line// /}" = "$line" ]; then
      pass
    else
      fail "line '$line' is $w px wide, over the width $width"
    fi
  done
done

# 4. Strings: quoted words keep blanks and '#', \" \\ and \n escapes; a
# forced break is a new line.
draw q1 <<SCRIPT || fail "quoted: $(cat "$work/err")"
size 200 60
font $sans 16
text 5 30 "a  #b \"c\""
SCRIPT
draw q2 <<SCRIPT || fail "quoted: $(cat "$work/err")"
size 200 60
font $sans 16
text 5 30 a  #b "c"
SCRIPT
cmp -s "$work/q1.ppm" "$work/q2.ppm" && fail "a quoted '#' starts a comment" || pass
"$ref" render "$work/ref.ppm" 200 60 "$sans" 16 5 30 start alphabetic 0 1.2 'a  #b "c"' &&
  same q1 ref "a quoted string is not the text between its quotes"
"$ref" render "$work/ref.ppm" 200 90 "$sans" 16 5 30 start alphabetic 0 1.2 $'one\ntwo' &&
  draw nl <<SCRIPT && same nl ref "\\n in a quoted string is not a line break"
size 200 90
font $sans 16
text 5 30 "one\ntwo"
SCRIPT
# family names: several words, and the family finds the same face as the file
draw fam <<SCRIPT || fail "family: $(cat "$work/err")"
size 200 60
font DejaVu Sans 16
text 5 30 Family
SCRIPT
draw file <<SCRIPT || fail "file: $(cat "$work/err")"
size 200 60
font $sans 16
text 5 30 Family
SCRIPT
same fam file "'font DejaVu Sans' is not DejaVuSans.ttf"
# style suffixes choose the face fontconfig has for them
for pair in "DejaVu Sans:bold=DejaVuSans-Bold" "DejaVu Serif:italic:bold=DejaVuSerif-BoldItalic" \
            "DejaVu Sans:weight=700=DejaVuSans-Bold" "DejaVu Serif:italic=DejaVuSerif-Italic"; do
  family=${pair%=*} face=${pair##*=}
  printf 'size 200 60\nfont %s 16\ntext 5 30 Family\n' "$family" | draw styled ||
    fail "font $family: $(cat "$work/err")"
  printf 'size 200 60\nfont %s 16\ntext 5 30 Family\n' "$(dirname "$sans")/$face.ttf" | draw face ||
    fail "font $face.ttf: $(cat "$work/err")"
  same styled face "'font $family' is not $face.ttf"
done
cmp -s "$work/styled.ppm" "$work/file.ppm" && fail "a style suffix draws the regular face" || pass
# text composites as fill does: the same colour and compositing
draw tc <<SCRIPT || fail "colour: $(cat "$work/err")"
size 100 40
compositing srgb
color #ff000080
font $sans 30
text 5 30 Red
SCRIPT
inked tc && pass || fail "translucent text drew nothing"

# glyphs are flattened within 0.01 px whatever a coarser `tolerance` says
draw coarse <<SCRIPT || fail "tolerance: $(cat "$work/err")"
tolerance 5
size 200 60
font $sans 16
text 5 30 Family
SCRIPT
same coarse file "text under 'tolerance 5' is not flattened within 0.01 px"
draw fine <<SCRIPT || fail "tolerance: $(cat "$work/err")"
tolerance 0.001
size 200 60
font $sans 16
text 5 30 Family
SCRIPT
cmp -s "$work/fine.ppm" "$work/file.ppm" && fail "text ignores a finer tolerance" || pass

# 5. Bad lines: one line naming the line, exit 1, no output.
bad() { # bad DESCRIPTION EXPECTED_MESSAGE_PART: script on stdin
  rm -f "$work/bad.ppm"
  "$cg" draw - -o "$work/bad.ppm" 2>"$work/err"
  local rc=$?
  if [ $rc = 1 ] && [ ! -e "$work/bad.ppm" ] && grep -q -- "$2" "$work/err"; then pass; else
    fail "$1: exit $rc, stderr '$(cat "$work/err")', want '$2'"; fi
  one_line "$1"
}
printf 'size 10 10\n\nfont NoSuchFamilyCg 12\n' | bad "unknown family" "<stdin>:3: no font family 'NoSuchFamilyCg' is installed"
printf 'size 10 10\nfont /nonexistent/cg.ttf 12\n' | bad "missing file" "<stdin>:2: cannot open the font file '/nonexistent/cg.ttf'"
printf 'size 10 10\nfont missing-cg.otf 12\n' | bad "missing file" "<stdin>:2: cannot open the font file 'missing-cg.otf'"
echo "not a font" > "$work/fake.ttf"
printf 'size 10 10\nfont %s 12\n' "$work/fake.ttf" | bad "not a font" "<stdin>:2: cannot load the font"
printf 'size 10 10\nfont %s 0\n' "$sans" | bad "size 0" "expected a font SIZE in pixels > 0"
printf 'size 10 10\nfont %s nan\n' "$sans" | bad "size nan" "<stdin>:2: expected a finite number for SIZE"
printf 'size 10 10\nfont DejaVu Sans:heavy 12\n' | bad "bad style" "<stdin>:2: unknown font style ':heavy'"
printf 'size 10 10\nfont DejaVu Sans:weight=2000 12\n' | bad "bad weight" "unknown font style ':weight=2000'"
printf 'size 10 10\nfont 12\n' | bad "no name" "'font' expects a family or file and a size"
printf 'size 10 10\ntext 1 2 hello\n' | bad "no font" "<stdin>:2: 'text' needs a font"
printf 'font %s 12\ntext 1 2 hello\n' "$sans" | bad "no canvas" "<stdin>:2: expected 'size W H'"
printf 'size 10 10\nfont %s 12\ntext 1 2\n' "$sans" | bad "no string" "'text' expects X, Y and a string"
printf 'size 10 10\nfont %s 12\ntext x 2 a\n' "$sans" | bad "bad X" "expected a number for X"
printf 'size 10 10\nfont %s 12\ntext 1 2e300 a\n' "$sans" | bad "huge Y" "is out of range"
printf 'size 10 10\nfont %s 12\ntext 1 2 \xff\xfe\n' "$sans" | bad "bad UTF-8" "<stdin>:3: cannot lay out the text: .*UTF-8"
printf 'size 10 10\ntext 1 2 "abc\n' | bad "unterminated" "<stdin>:2: unterminated quoted string"
printf 'size 10 10\ntext 1 2 "a"b\n' | bad "after quote" "expected a blank after the closing"
printf 'size 10 10\ntext 1 2 "\\q"\n' | bad "escape" "unknown escape in a quoted string"
printf 'size 10 10\nalign left\n' | bad "align" "expected start|middle|end after 'align', got 'left'"
printf 'size 10 10\nbaseline hanging\n' | bad "baseline" "expected alphabetic|top|middle|bottom"
printf 'size 10 10\nwrap -3\n' | bad "wrap" "expected WIDTH >= 0"
printf 'size 10 10\nlinespacing 0\n' | bad "linespacing" "expected a line spacing FACTOR > 0"
finish

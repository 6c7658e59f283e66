#!/usr/bin/env bash
# cg clip: the contract of line and boolean, pictures, bad input.
set -u
cg="$1"
src="$2"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
work="$tmp"
. "$src/tests/cli_checks.sh"
check() { # description, command output, expected
    if [ "$2" == "$3" ]; then pass; else fail "$1: got '$2', expected '$3'"; fi
}

check "line inside" "$("$cg" clip line 0 0 10 10 1 2 3 4)" "1 2 3 4"
check "line clipped" "$("$cg" clip line 0 0 10 10 -5 5 15 8)" "0 5.75 10 7.25"
check "line liang-barsky" "$("$cg" clip line 0 0 10 10 -5 5 15 8 --algorithm liang-barsky)" "0 5.75 10 7.25"
check "line rejected" "$("$cg" clip line 0 0 10 10 -5 15 15 18)" "rejected"
check "line rejected lb" "$("$cg" clip line 0 0 10 10 11 0 11 10 --algorithm=liang-barsky)" "rejected"
check "line point" "$("$cg" clip line 0 0 10 10 5 5 5 5)" "5 5 5 5"
check "line on edge" "$("$cg" clip line 0 0 10 10 -3 10 13 10)" "0 10 10 10"
# finite coordinates of any size: b - a overflows (1.7e308) or swamps the
# window (1e18) in doubles; the answer is the exact clip, rounded
for alg in cohen-sutherland liang-barsky; do
    check "line huge $alg" "$("$cg" clip line 0 0 10 10 1.7e308 0 -1.7e308 5 --algorithm $alg)" "10 2.5 0 2.5"
    check "line large $alg" "$("$cg" clip line 0 0 10 10 1e18 0 -1e18 5 --algorithm $alg)" "10 2.5 0 2.5"
done
check "trace last line" "$("$cg" clip line 0 0 10 10 -5 5 15 8 --trace | tail -1)" "0 5.75 10 7.25"
check "trace first step" "$("$cg" clip line 0 0 10 10 -5 5 15 8 --trace | head -1)" \
    "step 1: P0 (-5, 5) rCode 0001, P1 (15, 8) rCode 0010: clip left"
check "trace reject" "$("$cg" clip line 0 0 10 10 -5 11 -1 20 --trace | head -1)" \
    "step 1: P0 (-5, 11) rCode 1001, P1 (-1, 20) rCode 1001: trivial reject"
expect 2 "line bad number" "$cg" clip line 0 0 10 10 1 2 3 x
expect 2 "line too few" "$cg" clip line 0 0 10 10 1 2 3
expect 2 "line nan" "$cg" clip line 0 0 10 10 1 2 3 nan
expect 2 "line bad window" "$cg" clip line 10 0 0 10 1 2 3 4
expect 2 "line bad algorithm" "$cg" clip line 0 0 10 10 1 2 3 4 --algorithm foo

echo "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0))" > "$tmp/a.wkt"
echo "MULTIPOLYGON (((5 5, 15 5, 15 15, 5 15, 5 5)))" > "$tmp/b.wkt"
check "intersection" "$("$cg" clip boolean intersection "$tmp/a.wkt" "$tmp/b.wkt")" \
    "MULTIPOLYGON (((5 5, 10 5, 10 10, 5 10, 5 5)))"
check "union" "$("$cg" clip boolean union "$tmp/a.wkt" "$tmp/b.wkt")" \
    "MULTIPOLYGON (((0 0, 10 0, 10 5, 15 5, 15 15, 5 15, 5 10, 0 10, 0 0)))"
check "difference" "$("$cg" clip boolean difference "$tmp/a.wkt" "$tmp/b.wkt")" \
    "MULTIPOLYGON (((0 0, 10 0, 10 5, 5 5, 5 10, 0 10, 0 0)))"
check "stdin" "$("$cg" clip boolean intersection - "$tmp/b.wkt" < "$tmp/a.wkt")" \
    "MULTIPOLYGON (((5 5, 10 5, 10 10, 5 10, 5 5)))"
echo "MULTIPOLYGON EMPTY" > "$tmp/e.wkt"
check "empty" "$("$cg" clip boolean intersection "$tmp/a.wkt" "$tmp/e.wkt")" "MULTIPOLYGON EMPTY"
check "empty union" "$("$cg" clip boolean union "$tmp/e.wkt" "$tmp/a.wkt")" \
    "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)))"
# a hole given clockwise: even-odd and non-zero agree; both rings counter-clockwise: they differ
echo "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 8 2, 8 8, 2 8, 2 2))" > "$tmp/h.wkt"
check "evenodd hole" "$("$cg" clip boolean union "$tmp/h.wkt" "$tmp/e.wkt" --fill evenodd)" \
    "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 8 2, 2 2)))"
check "nonzero same direction" "$("$cg" clip boolean union "$tmp/h.wkt" "$tmp/e.wkt" --fill nonzero)" \
    "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)))"
check "negative" "$("$cg" clip boolean union "$tmp/h.wkt" "$tmp/e.wkt" --fill negative)" "MULTIPOLYGON EMPTY"
# one self-intersecting ring around a square and a triangle touching its edge:
# the result is a valid polygon, the triangle a hole of its own (not a ring
# through (2 0) twice)
echo "POLYGON ((0 0, 2 0, 1 2, 3 2, 2 0, 4 0, 4 4, 0 4, 0 0))" > "$tmp/pinch.wkt"
check "pinch split" "$("$cg" clip boolean union "$tmp/pinch.wkt" "$tmp/e.wkt" --fill evenodd)" \
    "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (2 0, 1 2, 3 2, 2 0)))"
"$cg" clip boolean xor "$tmp/a.wkt" "$tmp/b.wkt" --repeat 5 > /dev/null 2> "$tmp/time"
if grep -Eq '^boolean: [0-9]+\.[0-9]{2} ms$' "$tmp/time"; then pass; else
    fail "--repeat line: $(cat "$tmp/time")"; fi
expect 0 "picture" "$cg" clip boolean xor "$tmp/a.wkt" "$tmp/b.wkt" -o "$tmp/x.png"
if [ -s "$tmp/x.png" ]; then pass; else fail "no picture"; fi
expect 0 "polygon sh" "$cg" clip polygon "$tmp/b.wkt" "$tmp/a.wkt"
check "polygon sh output" "$(cat "$tmp/out")" "MULTIPOLYGON (((5 5, 10 5, 10 10, 5 10, 5 5)))"
expect 0 "polygon wa" "$cg" clip polygon "$tmp/b.wkt" "$tmp/a.wkt" --algorithm weiler-atherton

echo "POLYGON ((0 0, 1 x))" > "$tmp/bad.wkt"
expect 1 "bad wkt" "$cg" clip boolean union "$tmp/bad.wkt" "$tmp/a.wkt"
grep -q "offset" "$tmp/err" && pass || fail "no offset in message"
echo "POLYGON ((0 0, 1e999 0, 1 1, 0 0))" > "$tmp/inf.wkt"
expect 1 "infinite" "$cg" clip boolean union "$tmp/inf.wkt" "$tmp/a.wkt"
echo "LINESTRING (0 0, 1 1)" > "$tmp/line.wkt"
expect 1 "not a polygon" "$cg" clip boolean union "$tmp/line.wkt" "$tmp/a.wkt"
one_line "union of lines"
grep -q "only intersection and difference" "$tmp/err" && pass || fail "union of lines: $(cat "$tmp/err")"
# open paths: the pieces in order, the boundary inside for the intersection only
echo "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (3 3, 3 7, 7 7, 7 3, 3 3))" > "$tmp/holed.wkt"
echo "MULTILINESTRING ((-5 5, 15 5), (-5 0, 5 0, 5 -5), (-5 5, 0 10, -5 15))" > "$tmp/lines.wkt"
check "lines intersection" "$("$cg" clip boolean intersection "$tmp/lines.wkt" "$tmp/holed.wkt")" \
    "MULTILINESTRING ((0 5, 3 5), (7 5, 10 5), (0 0, 5 0))"
check "lines difference" "$("$cg" clip boolean difference "$tmp/lines.wkt" "$tmp/holed.wkt")" \
    "MULTILINESTRING ((-5 5, 0 5), (3 5, 7 5), (10 5, 15 5), (-5 0, 0 0), (5 0, 5 -5), (-5 5, 0 10), (0 10, -5 15))"
check "line backwards" "$(echo "LINESTRING (15 5, -5 5)" | "$cg" clip boolean intersection - "$tmp/holed.wkt")" \
    "MULTILINESTRING ((10 5, 7 5), (3 5, 0 5))"
check "line missing" "$(echo "LINESTRING (20 20, 30 30)" | "$cg" clip boolean intersection - "$tmp/holed.wkt")" \
    "MULTILINESTRING EMPTY"
"$cg" clip boolean intersection "$tmp/lines.wkt" "$tmp/holed.wkt" --repeat 3 > /dev/null 2> "$tmp/time"
if grep -Eq '^boolean: [0-9]+\.[0-9]{2} ms$' "$tmp/time"; then pass; else fail "lines timing: $(cat "$tmp/time")"; fi
expect 0 "lines picture" "$cg" clip boolean difference "$tmp/lines.wkt" "$tmp/holed.wkt" -o "$tmp/lines.png"
check "lines picture size" "$(png_size "$tmp/lines.png")" "640x640"
expect 1 "lines xor" "$cg" clip boolean xor "$tmp/lines.wkt" "$tmp/holed.wkt"
expect 1 "clip by lines" "$cg" clip boolean intersection "$tmp/holed.wkt" "$tmp/lines.wkt"
one_line "clip by lines"
echo "LINESTRING (0 0, nan 1)" > "$tmp/nanline.wkt"
expect 1 "nan line" "$cg" clip boolean intersection "$tmp/nanline.wkt" "$tmp/holed.wkt"
expect 1 "missing file" "$cg" clip boolean union "$tmp/nothere.wkt" "$tmp/a.wkt"
expect 2 "bad op" "$cg" clip boolean merge "$tmp/a.wkt" "$tmp/b.wkt"
expect 2 "bad fill" "$cg" clip boolean union "$tmp/a.wkt" "$tmp/b.wkt" --fill odd
expect 2 "bad repeat" "$cg" clip boolean union "$tmp/a.wkt" "$tmp/b.wkt" --repeat 0
expect 2 "bad sub" "$cg" clip circle
echo "POLYGON ((0 0, 10 0, 5 3, 0 10, 0 0))" > "$tmp/c.wkt"
expect 1 "concave window sh" "$cg" clip polygon "$tmp/c.wkt" "$tmp/a.wkt"
expect 0 "concave window wa" "$cg" clip polygon "$tmp/c.wkt" "$tmp/a.wkt" --algorithm weiler-atherton
# mutated WKT: every run ends with status 0 or 1 (never a crash)
base="MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 2 2)), ((20 20, 30 20, 25 30)))"
RANDOM=7
bad_exit=0
for i in $(seq 1 60); do
    text="$base"
    for k in 1 2 3; do
        pos=$((RANDOM % ${#text}))
        chars='(),. -e9x'
        c=${chars:$((RANDOM % ${#chars})):1}
        if [ $((RANDOM % 2)) == 0 ]; then text="${text:0:pos}$c${text:pos+1}"; else text="${text:0:pos}${text:pos+1}"; fi
    done
    printf '%s' "$text" > "$tmp/m.wkt"
    "$cg" clip boolean union "$tmp/m.wkt" "$tmp/a.wkt" > /dev/null 2>&1
    st=$?
    if [ $st -gt 1 ]; then echo "FAIL: status $st on '$text'"; bad_exit=1; fi
done
[ $bad_exit == 0 ] && pass || fail "mutated WKT ended with a status above 1"
finish

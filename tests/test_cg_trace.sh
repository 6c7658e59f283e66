#!/bin/bash
# cg trace: step tables compared with values worked by hand from the
# notes' algorithms, every algorithm's JSON, frames and page read back by
# outside tools (jq, python, xmllint, chromium), the examples of
# docs/teaching.md rerun, and bad input.
set -u
CG=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
fail=0
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# The cube back-face culling is traced on (examples/teaching/cube.obj).
cube=$dir/cube.obj
[ -n "${2:-}" ] && [ -f "$2/examples/teaching/cube.obj" ] && cube=$2/examples/teaching/cube.obj
[ -f "$cube" ] || printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n' >"$cube"
mkdir -p "$dir/examples/teaching" && cp "$cube" "$dir/examples/teaching/cube.obj"
# The other meshes the docs' examples trace.
[ -n "${2:-}" ] && cp "$2"/examples/teaching/*.obj "$dir/examples/teaching/" 2>/dev/null
# A triangle mesh for Loop's stencils and the edge operations: an octahedron.
octa=$dir/octahedron.obj
printf 'v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\nf 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n' >"$octa"
# The room the fills are traced in (examples/teaching/room.txt).
printf 'size 16 12\nbackground white\ncolor black\npolyline 1 1 14 1 14 10 1 10 1 1\nline 7 1 7 7\nline 10 4 14 4\n' \
    >"$dir/room.txt"
room=$dir/room.txt
[ -n "${2:-}" ] && [ -f "$2/examples/teaching/room.txt" ] && room=$2/examples/teaching/room.txt
"$CG" draw "$room" -o "$dir/room.png" || { echo "FAIL: cannot draw the room"; fail=1; }
check() { # name expected actual
    if [ "$2" != "$3" ]; then
        echo "FAIL: $1"; echo "expected:"; echo "$2"; echo "got:"; echo "$3"; fail=1
    fi
}
# The step rows only (step, f, move, f', pixel), blanks squeezed; the line's
# octant table (its own phase) is left out.
rows() {
    awk '/^[^ ].*:$/ { phase = $0 } phase != "octant:" && /^ +[0-9]+ /' |
        tr -s ' ' | sed 's/^ //'
}

# Line (0,0)-(8,3): dx = 8, dy = 3, f0 = 2dy - dx = -2, dE = 6, dNE = -10.
out=$("$CG" trace line 0 0 8 3) || { echo "FAIL: trace line exit"; fail=1; }
check "line header" "f = 2dy - dx = -2, dE = 2dy = 6, dNE = 2(dy - dx) = -10" \
      "$(echo "$out" | grep '^f = ')"
check "line steps" "0 - start -2 (0, 0)
1 -2 E 4 (1, 0)
2 4 NE -6 (2, 1)
3 -6 E 0 (3, 1)
4 0 E 6 (4, 1)
5 6 NE -4 (5, 2)
6 -4 E 2 (6, 2)
7 2 NE -8 (7, 3)
8 -8 E -2 (8, 3)" "$(echo "$out" | rows)"

# The same line given backwards is walked from (0, 0) too.
check "line reversed" "$(echo "$out" | rows)" "$("$CG" trace line 8 3 0 0 | rows)"

# A steep line in the third octant: (0,0)-(-2,5): dx = 5, dy = 2 after the
# exchange, f0 = -1, dE = 4, dNE = -6.
out=$("$CG" trace line 0 0 -2 5)
check "steep header" "f = 2dy - dx = -1, dE = 2dy = 4, dNE = 2(dy - dx) = -6" \
      "$(echo "$out" | grep '^f = ')"
check "steep steps" "0 - start -1 (0, 0)
1 -1 E 3 (0, 1)
2 3 NE -3 (-1, 2)
3 -3 E 1 (-1, 3)
4 1 NE -5 (-2, 4)
5 -5 E -1 (-2, 5)" "$(echo "$out" | rows)"

# Horizontal and single-pixel lines.
check "horizontal" "0 - start -3 (2, 2)
1 -3 E -3 (3, 2)
2 -3 E -3 (4, 2)
3 -3 E -3 (5, 2)" "$("$CG" trace line 2 2 5 2 | rows)"
check "single pixel" "0 - start 0 (4, 4)" "$("$CG" trace line 4 4 4 4 | rows)"

# Circle r = 7: f = 1 - r = -6, dE = 3, dSE = -2r + 5 = -9.
#   f < 0: E, f += dE; else SE, f += dSE; then dE += 2, dSE += 2 or 4.
out=$("$CG" trace circle 7) || { echo "FAIL: trace circle exit"; fail=1; }
check "circle steps" "0 - - - start -6 3 -9 (0, 7)
1 -6 3 -9 E -3 5 -7 (1, 7)
2 -3 5 -7 E 2 7 -5 (2, 7)
3 2 7 -5 SE -3 9 -1 (3, 6)
4 -3 9 -1 E 6 11 1 (4, 6)
5 6 11 1 SE 7 13 5 (5, 5)" "$(echo "$out" | rows)"
check "circle count" "6 steps; with 8-way symmetry the circle has 40 pixels" "$(echo "$out" | tail -n 1)"

# Circle r = 10: f0 = -9, dE = 3, dSE = -15.
check "circle 10" "0 - - - start -9 3 -15 (0, 10)
1 -9 3 -15 E -6 5 -13 (1, 10)
2 -6 5 -13 E -1 7 -11 (2, 10)
3 -1 7 -11 E 6 9 -9 (3, 10)
4 6 9 -9 SE -3 11 -5 (4, 9)
5 -3 11 -5 E 8 13 -3 (5, 9)
6 8 13 -3 SE 5 15 1 (6, 8)
7 5 15 1 SE 6 17 5 (7, 7)" "$("$CG" trace circle 10 | rows)"

check "circle 0" "1 step; with 8-way symmetry the circle has 1 pixel" "$("$CG" trace circle 0 | tail -n 1)"

# The notes' worked examples: the line from (1,1) to (22,9), dx = 21,
# dy = 8: f0 = 2dy - dx = -5, dE = 16, dNE = -26.
out=$("$CG" trace line 1 1 22 9)
check "notes line header" "f = 2dy - dx = -5, dE = 2dy = 16, dNE = 2(dy - dx) = -26" \
      "$(echo "$out" | grep '^f = ')"
check "notes line steps" "0 - start -5 (1, 1)
1 -5 E 11 (2, 1)
2 11 NE -15 (3, 2)
3 -15 E 1 (4, 2)
4 1 NE -25 (5, 3)
5 -25 E -9 (6, 3)
6 -9 E 7 (7, 3)
7 7 NE -19 (8, 4)
8 -19 E -3 (9, 4)
9 -3 E 13 (10, 4)
10 13 NE -13 (11, 5)
11 -13 E 3 (12, 5)
12 3 NE -23 (13, 6)
13 -23 E -7 (14, 6)
14 -7 E 9 (15, 6)
15 9 NE -17 (16, 7)
16 -17 E -1 (17, 7)
17 -1 E 15 (18, 7)
18 15 NE -11 (19, 8)
19 -11 E 5 (20, 8)
20 5 NE -21 (21, 9)
21 -21 E -5 (22, 9)" "$(echo "$out" | rows)"
check "notes line octant" "0 1 no no no 21 8 -5 16 -26" \
      "$(echo "$out" | sed -n '/^octant:$/,/^$/p' | grep -E '^ +[0-9]+ ' | tr -s ' ' | sed 's/^ //')"

# ... and the circle of radius 11: f = -10, dE = 3, dSE = -17.
check "notes circle 11" "0 - - - start -10 3 -17 (0, 11)
1 -10 3 -17 E -7 5 -15 (1, 11)
2 -7 5 -15 E -2 7 -13 (2, 11)
3 -2 7 -13 E 5 9 -11 (3, 11)
4 5 9 -11 SE -6 11 -7 (4, 10)
5 -6 11 -7 E 5 13 -5 (5, 10)
6 5 13 -5 SE 0 15 -1 (6, 9)
7 0 15 -1 SE -1 17 3 (7, 8)
8 -1 17 3 E 16 19 5 (8, 8)" "$("$CG" trace circle 11 | rows)"

# A line in each octant names its octant (1 to 8 counter-clockwise from +x).
octant=1
for end in "5 2" "2 5" "-2 5" "-5 2" "-5 -2" "-2 -5" "2 -5" "5 -2"; do
    # shellcheck disable=SC2086
    got=$("$CG" trace line 0 0 $end | sed -n 's/^octant \([0-9]\) .*/\1/p')
    check "octant of (0,0)-($end)" "$octant" "$got"
    octant=$((octant + 1))
done

# The midpoint ellipse 8 x 4: region 1 from (0, 4), d1 = 4F(x, y - 1/2):
# at x = 1, 4 * 16 * 1 + 64 * 7^2 - 4 * 64 * 16 = -896 (E).
out=$("$CG" trace ellipse 8 4)
check "ellipse region 1" "0 0 4 - start (0, -4)
1 1 4 -896 E (1, -4)
2 2 4 -704 E (2, -4)
3 3 4 -384 E (3, -4)
4 4 3 64 SE (4, -3)" "$(echo "$out" | sed -n '/^region 1:$/,/^$/p' | grep -E '^ +[0-9]+ ' | head -5 | tr -s ' ' | sed 's/^ //')"

# Liang-Barsky, worked by hand: (-5,2)-(15,6) against [0,10] x [0,8].
out=$("$CG" trace liang-barsky 0 0 10 8 -5,2 15,6)
check "liang-barsky boundaries" "0 left -20 -5 0.25 entering 0.25 1
1 right 20 15 0.75 leaving 0.25 0.75
2 bottom -4 2 -0.5 entering 0.25 0.75
3 top 4 6 1.5 leaving 0.25 0.75" \
      "$(echo "$out" | sed -n '/^boundaries:$/,/^$/p' | grep -E '^ +[0-9]+ ' | tr -s ' ' | sed 's/^ //')"
check "liang-barsky outcome" "0 accept (0, 3) (10, 5)" \
      "$(echo "$out" | sed -n '/^outcome:$/,/^$/p' | grep -E '^ +[0-9]+ ' | tr -s ' ' | sed 's/^ //')"

# Cohen-Sutherland by hand: (-5,2) is left (0001), (15,12) top and right
# (1010); clip left at y = 2 + 10 * 5/20 = 4.5, then top at x = 7.
check "cohen-sutherland" "0 (-5, 2) 0001 (15, 12) 1010 0 clip left
1 (0, 4.5) 0000 (15, 12) 1010 0 clip top
2 (0, 4.5) 0000 (7, 8) 0000 0 trivial accept" \
      "$("$CG" trace cohen-sutherland 0 0 10 8 -5,2 15,12 | sed -n '/^steps:$/,/^$/p' | grep -E '^ +[0-9]+ ' | tr -s ' ' | sed 's/^ //')"

# de Casteljau at t = 1/2 on (0,0) (10,20) (30,20) (40,0): Q = (20, 15).
check "casteljau point" "3 3 0.5 (20, 15) (20, 15)" \
      "$("$CG" trace casteljau 0.5 0,0 10,20 30,20 40,0 | grep -E '^ +3 ' | head -1 | tr -s ' ' | sed 's/^ //')"

# RGB (0.2, 0.4, 0.6) by hand: max 0.6, min 0.2, delta 0.4; V = 0.6,
# S = 0.4 / 0.6; L = 0.4, S = 0.4 / 0.8 = 0.5; H = 60 ((R - G) / delta + 4) = 210.
check "hsv result" "0 HSV [210 0.666667 0.6]" \
      "$("$CG" trace hsv 0.2 0.4 0.6 | sed -n '/^result:$/,/^$/p' | grep -E '^ +[0-9]+ ' | tr -s ' ' | sed 's/^ //')"
check "hsl result" "0 HSL [210 0.5 0.4]" \
      "$("$CG" trace hsl 0.2 0.4 0.6 | sed -n '/^result:$/,/^$/p' | grep -E '^ +[0-9]+ ' | tr -s ' ' | sed 's/^ //')"
# The point (1, 1, 0) seen from (0, 0, 5), 60 degrees, 640x480: eye (1, 1, -5),
# w = 5, x_ndc = (1 / tan 30 deg / (4/3)) / 5 = 0.2598, pixel x = 320 (1 + 0.2598).
# Seen straight on (no turn), a cube shows one face: 10 of 12 triangles culled.
check "backface straight on" "10 of 12 triangles culled" "$("$CG" trace backface "$cube" 0 0 | tail -n 1)"
check "pipeline pixel" "403" "$("$CG" trace pipeline 1,1,0 --json | jq '.steps[-1].pixels[0][0]')"

# Every algorithm of `cg help trace` runs, as a table and as JSON that an
# outside parser reads back with the same steps.
samples=("line 0 0 7 3" "dda 0 0 7 3" "wu 0 0 7 3" "circle 5" "ellipse 6 3"
         "hermite 0,0 10,0 5,10 5,-10 4" "bezier 0,0 2,8 8,8 10,0" "bspline 0,0 2,8 8,8 10,0 3"
         "catmull-rom 0,0 2,8 8,8 10,0" "casteljau 0.3 0,0 2,8 8,8 10,0"
         "flatten 0.5 0,0 20,40 60,40 80,0" "scanline 1,1|12,1|12,9|1,9;4,3|8,3|8,6|4,6 nonzero"
         "pipeline 1,1,0" "pipeline 1,1,0 3,2,6 0,0,0 45 320x200"
         "light 0,0,0 0,0,1 0,0,5" "light 0,0,0 0,0,1 0,0,5 ambient:0.1,0.1,0.1 directional:0,0,-1:1,1,1"
         "hsv 0.2 0.4 0.6" "hsl 1 1 1" "shading flat CUBE 80 60" "shading gouraud CUBE 80 60" "shading phong CUBE 70 50 160x120" "shading phong CUBE 0 0" "quantize 4 0 0.1 0.5 1.2" "dither floyd-steinberg 2 ramp:6x3" "dither bayer4 3 ramp:8x2" "dither bayer2 2 ROOM" "gamma 2.2 0 0.5 1" "vanishing 1,0,-1" "vanishing 0,1,0 0,0,5 0,0,0 50 320x240" "backface CUBE" "backface CUBE 0 0" "painter CUBE" "painter CUBE 0 0" "ray spheres 80 70" "ray CUBE 80 60 160x120" "ray spheres 0 0 40x30" "zbuffer CUBE 80 60" "face-loop CUBE 2" "one-ring CUBE 6" "loop OCTA 0" "catmull-clark CUBE 6" "catmull-clark OCTA 4" "edge-flip OCTA 0" "edge-split OCTA 3" "edge-collapse OCTA 5" "edge-flip CUBE 0" "zbuffer CUBE 0 0 40x30" "flood ROOM 3 3" "boundary ROOM 3 3 black 8" "cohen-sutherland 0 0 10 8 -5,2 15,12" "liang-barsky 0 0 10 8 -5,2 15,6"
         "sutherland-hodgman 0,0|10,0|10,10|0,10 -5,5|5,-5|15,5|5,15"
         "weiler-atherton 0,0|10,0|10,10|5,4|0,10 -2,3|12,3|12,7|-2,7"
         "frustum -3,0,0|3,0,0|0,3,-30" "frustum 0,0,0|1,0,0|0,1,0 3,3,3 0,0,0 40")
help=$("$CG" help trace)
for sample in "${samples[@]}"; do
    name=${sample%% *}
    # shellcheck disable=SC2206
    args=(${sample})
    args=("${args[@]//|/ }")
    args=("${args[@]/ROOM/$dir/room.png}")
    args=("${args[@]/CUBE/$cube}")
    args=("${args[@]/OCTA/$octa}")
    echo "$help" | grep -qE "^  $name " || { echo "FAIL: 'cg help trace' does not name $name"; fail=1; }
    table=$("$CG" trace "${args[@]}") || { echo "FAIL: cg trace $sample"; fail=1; continue; }
    rows_in_table=$(echo "$table" | grep -cE '^ +[0-9]+ ')
    json=$("$CG" trace "${args[@]}" --json) || { echo "FAIL: cg trace $sample --json"; fail=1; continue; }
    if command -v jq >/dev/null; then
        steps=$(echo "$json" | jq '.steps | length') || { echo "FAIL: $name: JSON does not parse"; fail=1; continue; }
        check "$name: JSON algorithm" "$name" "$(echo "$json" | jq -r .algorithm)"
        check "$name: JSON steps = table rows" "$rows_in_table" "$steps"
        check "$name: JSON step indices" "$(seq 0 $((steps - 1)) | tr '\n' ' ')" \
              "$(echo "$json" | jq -r '.steps[].index' | tr '\n' ' ')"
    else
        python3 -c 'import json,sys; json.load(sys.stdin)' <<<"$json" || { echo "FAIL: $name: JSON"; fail=1; }
    fi
done

# JSON pixels are the table's pixels (line 1 1 22 9), read by jq.
if command -v jq >/dev/null; then
    check "line JSON pixels" "$("$CG" trace line 1 1 22 9 | rows | sed 's/.*(\(.*\), \(.*\))/\1 \2/')" \
          "$("$CG" trace line 1 1 22 9 --json | jq -r '.steps[] | select(.phase == "walk") | .pixels[0] | "\(.[0]) \(.[1])"')"
    check "circle JSON null f at start" "null" "$("$CG" trace circle 4 --json | jq '.steps[0].values.f')"
fi

# --frames: one PNG per step, each a real PNG (signature and size read back
# by python), the pictures changing from step to step.
"$CG" trace line 1 1 22 9 --frames "$dir/frames" >/dev/null || { echo "FAIL: --frames"; fail=1; }
check "frame count" "23" "$(ls "$dir/frames" | grep -c '^step_[0-9]\{4\}\.png$')"
sizes=$(python3 - "$dir/frames" <<'PY'
import struct, sys, os, zlib
folder = sys.argv[1]
seen = set()
for name in sorted(os.listdir(folder)):
    data = open(os.path.join(folder, name), 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', name
    width, height = struct.unpack('>II', data[16:24])
    seen.add(zlib.crc32(data))
    print(width, height)
print('distinct', len(seen))
PY
)
check "frames all one size" "1" "$(echo "$sizes" | grep -v distinct | sort -u | wc -l)"
check "frames differ" "distinct 23" "$(echo "$sizes" | tail -n 1)"

# --html: one page holding every frame inline, and the steps; no network.
"$CG" trace circle 11 --html "$dir/circle.html" >/dev/null || { echo "FAIL: --html"; fail=1; }
check "page frames" "9" "$(grep -o 'data:image/png;base64,' "$dir/circle.html" | wc -l)"
check "page network" "0" "$(grep -cE 'src="https?:|href="https?:' "$dir/circle.html")"
if command -v xmllint >/dev/null; then
    xmllint --html --noout "$dir/circle.html" 2>"$dir/lint" || true
    check "page parses as HTML" "" "$(grep -v 'Tag nav\|Tag main' "$dir/lint")"
fi
# In a headless browser the script runs: the first step is shown and the
# table holds one row per step.
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -n "$browser" ]; then
    dom=$(timeout 120 "$browser" --headless --no-sandbox --disable-gpu --dump-dom \
          "file://$dir/circle.html" 2>/dev/null)
    check "page shows step 1" "1" "$(echo "$dom" | grep -c 'id="where">step 1 of 9 ')"
    check "page table rows" "9" "$(echo "$dom" | grep -o 'data-i="[0-9]*"' | wc -l)"
else
    echo "note: chromium not found: the page's script is not run (apt-get install chromium)"
fi
# The frames of --html alone go to a temporary folder that is removed.
left=$(ls -d /tmp/cg-trace-* 2>/dev/null | wc -l)
"$CG" trace dda 0 0 5 2 --html "$dir/dda.html" >/dev/null
check "temporary frames removed" "$left" "$(ls -d /tmp/cg-trace-* 2>/dev/null | wc -l)"

# A non-convex window, and --frames into a file that is not a folder.
"$CG" trace sutherland-hodgman "0,0 10,0 2,2 0,10" "1,1 3,1 3,3" >/dev/null 2>"$dir/err" &&
    { echo "FAIL: a non-convex window is accepted"; fail=1; }
grep -q convex "$dir/err" || { echo "FAIL: the non-convex window's message"; fail=1; }
touch "$dir/plain"
"$CG" trace line 0 0 3 1 --frames "$dir/plain" >/dev/null 2>"$dir/err" &&
    { echo "FAIL: --frames into a file"; fail=1; }
[ -s "$dir/err" ] || { echo "FAIL: --frames into a file: no message"; fail=1; }

# The examples of docs/teaching.md are what the command prints today.
docs=${2:-}/docs/teaching.md
if [ -n "${2:-}" ] && [ -f "$docs" ]; then
    count=0
    while IFS= read -r command; do
        expected=$(awk -v c="$command" '$0 == "$ " c { on = 1; next } on && /^```/ { exit } on' "$docs")
        actual=$(cd "$dir" && eval "\"$CG\" ${command#cg }")
        check "docs example: $command" "$expected" "$actual"
        count=$((count + 1))
    done < <(sed -n 's/^\$ \(cg trace .*\)/\1/p' "$docs")
    [ "$count" -ge 8 ] || { echo "FAIL: docs/teaching.md has only $count examples"; fail=1; }
fi

# Bad input: usage errors (exit 2) with a message on stderr.
for args in "line 0 0 8" "line 0 0 8 x" "circle -1" "circle 1.5" "square 3" "" \
            "line 0 0 2147483648 0" "line 0 0 200000 0" "ellipse 5 5" "ellipse 5" \
            "ellipse 30000 2" "dda 0 0 1" "wu 0 0 300000 1" "bezier 0,0 1,1 2,2" "bezier 0,0 1,1 2,2 3,x" \
            "hermite 0,0 1,1 2,2 3,3 0" "casteljau 0.5 0,0" "casteljau nan 0,0 1,1" \
            "flatten 0 0,0 1,1" "flatten 1e-30 0,0 1e6,1e6 2e6,0" "liang-barsky 10 0 0 10 0,0 1,1" \
            "liang-barsky 0 0 10 10 0,0" "sutherland-hodgman 0,0 1,1" "weiler-atherton 0,0|1,0|0,1 0,0|1,1" "pipeline 1,1" "pipeline 0,0,0 0,0,0" \
            "pipeline 0,0,0 0,0,5 0,0,0 200" "light 0,0,0 0,0,0 0,0,5" "light 0,0,0 0,0,1 0,0,5 spot:1,1,1" \
            "light 0,0,0 0,0,1 0,0,5 ambient:-1,0,0" "hsv 0.2 0.4" "hsl a b c" "backface /nonexistent.obj" "painter /nonexistent.obj" "shading toon $cube 1 1" "shading phong $cube 160 0" "shading phong /nonexistent.obj 1 1" "shading flat $cube 1" "ray spheres 160 0" "ray spheres 1" "ray /nonexistent.obj 1 1" "ray spheres 1 1 0x5" "loop $cube 0" "loop $octa 6" "catmull-clark $octa -1" "edge-flip $octa 12" "edge-split $octa x" "edge-collapse /nonexistent.obj 0" "edge-flip $octa" "quantize 1 0.5" "quantize 4" "quantize 4 nan" "dither bayer3 2 ramp:4x4" "dither bayer2 2 ramp:65x2" "dither floyd-steinberg 300 ramp:4x4" "dither bayer2 2 /nonexistent.png" "gamma 0 0.5" "gamma -1 0.5" "gamma 2.2" "painter $cube x" "painter $cube 0 0 0" "vanishing 0,0,0" "liang-barsky 0 0 10 10 -1e308,0 1e308,5 --frames $dir/huge" "frustum 0,0,0|1,0,0" "face-loop $cube 6" "one-ring $cube 8" "one-ring $cube -1" "frustum 0,0,0|1,0,0|0,1 " "frustum 0,0,0|1,0,0|0,1,0 0,0,0 0,0,0" "vanishing 1,0" "zbuffer $cube 160 0" "zbuffer $cube 0 -1" "zbuffer $cube 1" "backface $dir/room.txt" "scanline 0,0 1,1" "scanline 0,0;1,1;2,2" \
            "scanline 0,0|5,0|0,5 odd" "scanline 0,0|9000,0|0,5" \
            "line 0 0 5 5 --bogus" "line 0 0 5 5 --frames" "circle 3 --html="; do
    # words split at blanks; '|' inside a word stands for a blank
    # shellcheck disable=SC2206
    words=($args)
    words=("${words[@]//|/ }")
    "$CG" trace "${words[@]}" >/dev/null 2>/tmp/cg_trace_err.$$
    status=$?
    if [ $status -eq 0 ] || [ ! -s /tmp/cg_trace_err.$$ ]; then
        echo "FAIL: 'cg trace $args' should fail with a message (status $status)"; fail=1
    fi
done
rm -f /tmp/cg_trace_err.$$
[ $fail -eq 0 ] && echo "cg trace: all checks passed"
exit $fail

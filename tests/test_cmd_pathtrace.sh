#!/usr/bin/env bash
# `cg render MESH --algorithm pathtrace` and `cg merge`: outputs, tiles and
# sample ranges merged byte-identical to the whole render, bad input errors
# that leave an existing output untouched.
# usage: test_cmd_pathtrace.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mesh="$src/examples/teaching/cube.obj"
common=(--algorithm pathtrace --size 24x16 --spp 6 --seed 5 --max-depth 4 --quiet)

fail() { echo "FAIL: $*"; failed=1; }

run() { "$cg" render "$mesh" "${common[@]}" "$@" 2>"$tmp/err" || fail "render $* exited non-zero: $(cat "$tmp/err")"; }

# expect_error "TEXT" ARGS...: exit status 2 (usage) or 1, the text in one line.
expect_error() {
  local text="$1"
  shift
  echo keep >"$tmp/kept.png"
  if "$cg" "$@" -o "$tmp/kept.png" 2>"$tmp/err"; then
    fail "cg $* succeeded"
  elif ! grep -q -- "$text" "$tmp/err"; then
    fail "cg $*: expected '$text', got '$(cat "$tmp/err")'"
  elif [ "$(wc -l <"$tmp/err")" -ne 1 ]; then
    fail "cg $*: more than one line: $(cat "$tmp/err")"
  fi
  [ "$(cat "$tmp/kept.png")" = keep ] || fail "cg $* touched the existing output"
}

run -o "$tmp/whole.pfm"
run -o "$tmp/whole.png"
run -o "$tmp/whole.part"
head -c 2 "$tmp/whole.pfm" | grep -q PF || fail "whole.pfm is not a PFM"
[ "$(wc -c <"$tmp/whole.pfm")" -eq $((24 * 16 * 12 + 14)) ] || fail "whole.pfm has the wrong size"
file "$tmp/whole.png" 2>/dev/null | grep -q "PNG image data, 24 x 16" \
  || head -c 8 "$tmp/whole.png" | grep -q PNG || fail "whole.png is not a PNG"

# Same bytes on 1 and 2 threads.
run --threads 2 -o "$tmp/threads.pfm"
cmp -s "$tmp/whole.pfm" "$tmp/threads.pfm" || fail "2 threads differ from 1"

# Four tiles merged.
run --tile 0,0,10,7 -o "$tmp/t1.part"
run --tile 10,0,24,7 -o "$tmp/t2.part"
run --tile 0,7,10,16 -o "$tmp/t3.part"
run --tile 10,7,24,16 -o "$tmp/t4.part"
"$cg" merge "$tmp"/t1.part "$tmp"/t2.part "$tmp"/t3.part "$tmp"/t4.part -o "$tmp/tiles.pfm" \
  || fail "merge of tiles failed"
cmp -s "$tmp/whole.pfm" "$tmp/tiles.pfm" || fail "merged tiles differ from the whole render"
"$cg" merge "$tmp"/t4.part "$tmp"/t2.part "$tmp"/t3.part "$tmp"/t1.part -o "$tmp/tiles.png" \
  || fail "merge of tiles to png failed"
cmp -s "$tmp/whole.png" "$tmp/tiles.png" || fail "merged tiles (png) differ from the whole render"

# Sample ranges merged, and a tile of a sample range.
run --sample-range 0..2 -o "$tmp/r1.part"
run --sample-range 2..6 -o "$tmp/r2.part"
"$cg" merge "$tmp/r1.part" "$tmp/r2.part" -o "$tmp/ranges.pfm" || fail "merge of ranges failed"
cmp -s "$tmp/whole.pfm" "$tmp/ranges.pfm" || fail "merged ranges differ from the whole render"
"$cg" merge "$tmp/r1.part" "$tmp/r2.part" -o "$tmp/ranges.part" || fail "merge to a part failed"
cmp -s "$tmp/whole.part" "$tmp/ranges.part" || fail "merged part differs from the whole part"

# A different seed changes the picture.
"$cg" render "$mesh" --algorithm pathtrace --size 24x16 --spp 6 --seed 6 --max-depth 4 --quiet \
  -o "$tmp/seed.pfm" || fail "seed 6 render failed"
cmp -s "$tmp/whole.pfm" "$tmp/seed.pfm" && fail "another seed gave the same picture"

# A time budget stops early and still writes a picture; progress on stderr.
"$cg" render "$mesh" --algorithm pathtrace --size 24x16 --spp 100000 --time 0.2 \
  -o "$tmp/timed.png" 2>"$tmp/progress" || fail "--time render failed"
grep -q "pathtrace: .* samples" "$tmp/progress" || fail "no progress on stderr"
[ -s "$tmp/timed.png" ] || fail "--time wrote no picture"

# Bad input.
pt=(render "$mesh" --algorithm pathtrace --size 24x16 --spp 6 --quiet)
expect_error "--spp" "${pt[@]}" --spp 0
expect_error "--max-depth" "${pt[@]}" --max-depth 0
expect_error "--tile" "${pt[@]}" --tile 0,0,30,5
expect_error "--tile" "${pt[@]}" --tile 5,5,5,8
expect_error "--tile" "${pt[@]}" --tile 1,2,3
expect_error "--sample-range" "${pt[@]}" --sample-range 4..9
expect_error "--sample-range" "${pt[@]}" --sample-range 3..3
expect_error ".part" "${pt[@]}" --tile 0,0,4,4
expect_error "--environment-color" "${pt[@]}" --environment-color 1,-1,1
expect_error "--environment-color" "${pt[@]}" --environment-color 1,1
expect_error "missing-sky.hdr" "${pt[@]}" --environment "$tmp/missing-sky.hdr"
expect_error "give one sky" "${pt[@]}" --environment "$tmp/sky1.pfm" --environment-color 1,1,1
expect_error "--seed" "${pt[@]}" --seed -1
expect_error "missing.obj" render "$tmp/missing.obj" --algorithm pathtrace --quiet
expect_error "not a cg part file" merge "$tmp/whole.pfm"
expect_error "samples" merge "$tmp/r1.part"
cp "$tmp/r2.part" "$tmp/short.part"
truncate -s -5 "$tmp/short.part"
expect_error "truncated" merge "$tmp/r1.part" "$tmp/short.part"
"$cg" render "$mesh" --algorithm pathtrace --size 24x16 --spp 6 --seed 9 --quiet \
  --sample-range 2..6 -o "$tmp/r2seed.part" || fail "seed 9 part failed"
expect_error "another render" merge "$tmp/r1.part" "$tmp/r2seed.part"
run --sample-range 2..6 --environment-color 0.5,0.5,0.5 -o "$tmp/r2sky.part"
expect_error "another render" merge "$tmp/r1.part" "$tmp/r2sky.part"
expect_error "expected PARTS" merge

# Float outputs through the image library: an EXR (when cg has OpenEXR)
# holds the render, and converting it to PNG with the same filmic curve
# gives the bytes a direct PNG render gives (half floats round the same).
run -o "$tmp/whole.png"
if run -o "$tmp/whole.exr" 2>/dev/null; then
  [ "$(head -c 4 "$tmp/whole.exr" | od -An -tx1 | tr -d ' ')" = 762f3101 ] \
    || fail "whole.exr is not an OpenEXR file"
  "$cg" convert "$tmp/whole.pfm" "$tmp/from-pfm.png" --tonemap filmic \
    || fail "convert of the PFM failed"
  cmp -s "$tmp/whole.png" "$tmp/from-pfm.png" || fail "PFM converted to PNG differs from the PNG render"
fi

# Environment maps: a one-pixel file is the uniform sky of its colour, to
# the byte; a sky that is bright only overhead lights the mesh differently.
pfm() { # FILE WIDTH HEIGHT R G B: a PFM of one colour (little-endian floats)
  python3 -c 'import struct,sys; f,w,h,r,g,b=sys.argv[1:]; w,h=int(w),int(h)
open(f,"wb").write(b"PF\n%d %d\n-1.0\n" % (w,h) + struct.pack("<3f",float(r),float(g),float(b))*(w*h))' "$@"
}
if command -v python3 >/dev/null; then
  pfm "$tmp/sky1.pfm" 1 1 0.5 0.25 1
  run --environment "$tmp/sky1.pfm" -o "$tmp/sky-map.pfm"
  run --environment-color 0.5,0.25,1 -o "$tmp/sky-color.pfm"
  cmp -s "$tmp/sky-map.pfm" "$tmp/sky-color.pfm" || fail "a one-pixel sky differs from --environment-color"
  # 8 x 4 map, top row bright, the rest black
  python3 -c 'import struct,sys; rows=[(4.0,4.0,4.0)]+[(0.0,0.0,0.0)]*3
data=b"".join(struct.pack("<3f",*rows[3-y])*8 for y in range(4))
open(sys.argv[1],"wb").write(b"PF\n8 4\n-1.0\n"+data)' "$tmp/sky-top.pfm"
  run --environment "$tmp/sky-top.pfm" -o "$tmp/sky-top-render.pfm"
  cmp -s "$tmp/sky-top-render.pfm" "$tmp/sky-color.pfm" && fail "a map with a bright top renders as a uniform sky"
  # --environment-intensity scales the map: a 0.25,0.125,0.5 pixel at 2 is
  # the 0.5,0.25,1 sky, to the byte (powers of two scale exactly)
  pfm "$tmp/sky-half.pfm" 1 1 0.25 0.125 0.5
  run --environment "$tmp/sky-half.pfm" --environment-intensity 2 -o "$tmp/sky-scaled.pfm"
  cmp -s "$tmp/sky-scaled.pfm" "$tmp/sky-color.pfm" || fail "--environment-intensity 2 does not double the map"
  expect_error "scales an --environment map" "${pt[@]}" --environment-intensity 2
  expect_error "--environment-intensity" "${pt[@]}" --environment "$tmp/sky1.pfm" --environment-intensity -1
  # parts under another intensity belong to another render
  run --sample-range 0..2 --environment "$tmp/sky1.pfm" -o "$tmp/i1.part"
  run --sample-range 2..6 --environment "$tmp/sky1.pfm" --environment-intensity 3 -o "$tmp/i3.part"
  expect_error "another render" merge "$tmp/i1.part" "$tmp/i3.part"
  run --sample-range 2..6 --environment "$tmp/sky1.pfm" -o "$tmp/i1b.part"
  "$cg" merge "$tmp/i1.part" "$tmp/i1b.part" -o "$tmp/i1.pfm" || fail "merge of parts under one sky failed"
fi

# Scene files: their size unless --size, their objects, materials, lights
# and camera, and their "environment" (a file relative to the scene, with an
# intensity, or a colour; the background colour without the key).
scene() { # FILE ENVIRONMENT-JSON-OR-EMPTY FLOOR-MATERIAL
  local environment=""
  [ -n "$2" ] && environment="\"environment\": $2,"
  cat >"$1" <<JSON
{"image": {"width": 40, "height": 24, "background": [0.2, 0.2, 0.2]},
 "camera": {"eye": [0, 1.5, 4], "target": [0, 0.5, 0], "fov": 50},
 $environment
 "lights": [{"type": "directional", "direction": [0.3, -1, -0.2], "color": [1, 1, 1]}],
 "materials": {"floor": $3, "red": {"color": [0.8, 0.2, 0.1], "kd": 1}},
 "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
             {"type": "sphere", "center": [0, 0.6, 0], "radius": 0.6, "material": "red"}]}
JSON
}
plain='{"color": [0.7, 0.7, 0.7], "kd": 1}'
checker='{"color": [0.7, 0.7, 0.7], "kd": 1, "checker": {"color": [0.1, 0.1, 0.1], "size": 0.5}}'
st=(--algorithm pathtrace --spp 4 --seed 2 --max-depth 3 --quiet)
scene "$tmp/s.json" "" "$plain"
"$cg" render "$tmp/s.json" "${st[@]}" -o "$tmp/s.pfm" 2>"$tmp/err" || fail "scene render failed: $(cat "$tmp/err")"
[ "$(head -c 20 "$tmp/s.pfm" | sed -n 2p)" = "40 24" ] || fail "a scene's own size is not used"
"$cg" render "$tmp/s.json" "${st[@]}" --size 20x12 -o "$tmp/s-small.pfm" || fail "scene --size failed"
[ "$(head -c 20 "$tmp/s-small.pfm" | sed -n 2p)" = "20 12" ] || fail "--size does not override a scene's size"
# the background is the sky without the key: the same bytes as that colour
"$cg" render "$tmp/s.json" "${st[@]}" --environment-color 0.2,0.2,0.2 -o "$tmp/s-bg.pfm"
cmp -s "$tmp/s.pfm" "$tmp/s-bg.pfm" || fail "a scene without environment is not lit by its background"
scene "$tmp/s-color.json" '{"color": [0.5, 0.25, 1]}' "$plain"
"$cg" render "$tmp/s-color.json" "${st[@]}" -o "$tmp/s-color.pfm"
"$cg" render "$tmp/s.json" "${st[@]}" --environment-color 0.5,0.25,1 -o "$tmp/s-cli.pfm"
cmp -s "$tmp/s-color.pfm" "$tmp/s-cli.pfm" || fail "environment.color differs from --environment-color"
if command -v python3 >/dev/null; then
  mkdir -p "$tmp/skies"
  pfm "$tmp/skies/half.pfm" 1 1 0.25 0.125 0.5
  scene "$tmp/s-file.json" '{"file": "skies/half.pfm", "intensity": 2}' "$plain"
  "$cg" render "$tmp/s-file.json" "${st[@]}" -o "$tmp/s-file.pfm" 2>"$tmp/err" \
    || fail "environment.file failed: $(cat "$tmp/err")"
  cmp -s "$tmp/s-file.pfm" "$tmp/s-color.pfm" || fail "environment.file x intensity differs from the colour"
fi
# the checker of the ray tracer's floors is drawn too
scene "$tmp/s-checker.json" "" "$checker"
"$cg" render "$tmp/s-checker.json" "${st[@]}" -o "$tmp/s-checker.pfm"
cmp -s "$tmp/s.pfm" "$tmp/s-checker.pfm" && fail "a checkered floor renders as a plain one"
# parts of a scene merge to the whole render; another scene's parts do not
sp=(render "$tmp/s.json" "${st[@]}")
"$cg" "${sp[@]}" --tile 0,0,40,10 -o "$tmp/s1.part" && "$cg" "${sp[@]}" --tile 0,10,40,24 -o "$tmp/s2.part" \
  || fail "scene parts failed"
"$cg" merge "$tmp/s1.part" "$tmp/s2.part" -o "$tmp/s-merged.pfm" || fail "merge of scene parts failed"
cmp -s "$tmp/s.pfm" "$tmp/s-merged.pfm" || fail "merged scene parts differ from the whole"
"$cg" render "$tmp/s-checker.json" "${st[@]}" --tile 0,10,40,24 -o "$tmp/s3.part"
expect_error "another render" merge "$tmp/s1.part" "$tmp/s3.part"
# an emitting material ("emission") seen directly, black and unlit, gives
# its radiance in the middle pixel
if command -v python3 >/dev/null; then
  scene "$tmp/s-glow.json" '{"color": [0, 0, 0]}' '{"color": [0, 0, 0], "kd": 1, "emission": [0.5, 0.25, 2]}'
  "$cg" render "$tmp/s-glow.json" "${st[@]}" -o "$tmp/s-glow.pfm" || fail "emission scene failed"
  python3 -c 'import struct,sys
d=open(sys.argv[1],"rb").read().split(b"\n",3); w,h=map(int,d[1].split())
px=struct.unpack("<%df"%(3*w*h),d[3])
r,g,b=px[3*(w//2):3*(w//2)+3]   # the bottom row comes first in a PFM: the floor
sys.exit(0 if abs(r-0.5)<1e-5 and abs(g-0.25)<1e-5 and abs(b-2)<1e-5 else 1)' "$tmp/s-glow.pfm" \
    || fail "an emitting floor seen directly is not its emission"
fi
# bad environments: the JSON path and what was expected
scene "$tmp/bad1.json" '{"intensity": 2}' "$plain"
expect_error "environment.intensity" render "$tmp/bad1.json" "${st[@]}"
scene "$tmp/bad2.json" '{"file": "sky.hdr", "color": [1, 1, 1]}' "$plain"
expect_error "a file or a color" render "$tmp/bad2.json" "${st[@]}"
scene "$tmp/bad3.json" '{"file": "missing.hdr"}' "$plain"
expect_error "missing.hdr" render "$tmp/bad3.json" "${st[@]}"
scene "$tmp/bad4.json" '{"colour": [1, 1, 1]}' "$plain"
expect_error "colour" render "$tmp/bad4.json" "${st[@]}"

[ "$failed" -eq 0 ] && echo "test_cmd_pathtrace: all passed"
exit "$failed"

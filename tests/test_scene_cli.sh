#!/usr/bin/env bash
# `cg render SCENE.json`: every example scene renders with every algorithm
# (mirrors and glass with the ray tracer only),
# command-line options override the scene, overlays are drawn, and bad scenes
# give one clear line and write nothing.
# Usage: test_scene_cli.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1" source_dir="$2"
. "$source_dir/tests/cli_checks.sh"

for scene in "$source_dir"/examples/scenes/*.json; do
  name=$(basename "$scene" .json)
  for algorithm in zbuffer painter raytrace; do
    out="$work/$name-$algorithm.png"
    if [ "$algorithm" != raytrace ] && grep -q '"reflectance"' "$scene"; then
      # Mirrors and glass: the rasterizer refuses them by name.
      "$cg" render "$scene" --algorithm "$algorithm" --size 96x64 -o "$out" 2>"$work/err"
      [ $? = 1 ] && grep -q "reflectance: the z-buffer and the painter's algorithm draw no reflections" \
        "$work/err" && [ ! -e "$out" ] && pass || fail "$name $algorithm: mirrors not refused: $(cat "$work/err")"
      continue
    fi
    if "$cg" render "$scene" --algorithm "$algorithm" --size 96x64 -o "$out" 2>"$work/err"; then
      [ -s "$out" ] && pass || fail "$name $algorithm: no picture"
    else
      fail "$name $algorithm: $(cat "$work/err")"
    fi
  done
done

# --size overrides the scene's size.
"$cg" convert "$work/bunny-zbuffer.png" "$work/size.ppm" 2>/dev/null
head -c 20 "$work/size.ppm" | tr '\n' ' ' | grep -q "P6 96 64" && pass || fail "--size not applied"

# Overlays are drawn: the same scene without them differs.
sed 's/"overlays": \[.*\]/"overlays": []/' "$source_dir/examples/scenes/bunny.json" > "$work/plain.json"
sed -i "s|../../data|$source_dir/data|" "$work/plain.json"
sed 's/"overlays": \[\]/"overlays": ["color red", "line 0 0 95 63"]/' "$work/plain.json" > "$work/lined.json"
"$cg" render "$work/plain.json" --size 96x64 -o "$work/plain.png" 2>/dev/null
"$cg" render "$work/lined.json" --size 96x64 -o "$work/lined.png" 2>/dev/null
[ -s "$work/plain.png" ] && [ -s "$work/lined.png" ] && ! cmp -s "$work/plain.png" "$work/lined.png" \
  && pass || fail "overlays changed nothing"

# Bad scenes: one line naming the JSON path, exit 1, nothing written.
check_bad() { # check_bad JSON TEXT
  printf '%s' "$1" > "$work/bad.json"
  "$cg" render "$work/bad.json" -o "$work/bad.png" 2>"$work/err"
  local status=$?
  [ "$status" = 1 ] && pass || fail "bad scene exit $status: $1"
  grep -qF "$2" "$work/err" && pass || fail "message '$(cat "$work/err")' lacks '$2'"
  [ "$(wc -l < "$work/err")" = 1 ] && pass || fail "more than one line for: $1"
  [ ! -e "$work/bad.png" ] && pass || fail "output written for a bad scene"
}
check_bad '{"camera": {"fov": "wide"}}' 'camera.fov: expected a number between 1 and 179, got "wide"'
check_bad '{"image": {"width": 1000000000, "height": 1000000000}}' 'image.width'
check_bad '{"objects": [{"type": "mesh", "file": "missing.obj"}]}' 'objects[0].file'
check_bad '{"objects": [' 'malformed JSON'
check_bad '{"colour": 1}' 'colour: unknown key'
check_bad '{"camera": {"projection": "cavalier"}, "render": {"algorithm": "raytrace"}}' 'oblique'
check_bad '{"overlays": ["line 0 0 zz 1"]}' 'bad.json: overlays[0]: expected an integer for X1'
check_bad '{"overlays": ["color red", "aacircle 10 10 1e12"]}' 'bad.json: overlays[1]: R = 1e12 is out of range'
check_bad '{"overlays": ["color red", "bogus 1"]}' "bad.json: overlays[1]: unknown command 'bogus'"
check_bad '{"objects": [{"type": "box", "lo": [0, 0, 0], "hi": [1, 0, 1]}]}' 'bad.json: objects[0].hi: expected every coordinate of hi to be greater than that of lo'
check_bad '{"objects": [{"type": "box", "lo": [0, 0, 0], "hi": [1, 0, 1]}], "render": {"algorithm": "raytrace"}}' 'objects[0].hi'
cp "$work/bunny-zbuffer.png" "$work/keep.png"
printf '{"camera": {"fov": 0}}' > "$work/bad.json"
"$cg" render "$work/bad.json" -o "$work/keep.png" 2>/dev/null
cmp -s "$work/keep.png" "$work/bunny-zbuffer.png" && pass || fail "a failed render replaced an existing picture"
"$cg" render "$work/nothing-here.json" -o "$work/x.png" 2>"$work/err"
[ $? = 1 ] && grep -q "cannot open" "$work/err" && pass || fail "missing scene file"

finish

#!/usr/bin/env bash
# `cg render SCENE --frames A..B`: one image per frame of the scene's
# animation, named from OUT; each frame byte-identical to a still scene
# holding that frame's values; the errors of bad ranges and inputs.
# usage: test_cmd_render_frames.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; failed=1; }

# A small scene: two keys of the eye (linear), a box turning a quarter, the
# directional light from 0.5 to 1.5 times its colour.
still() { # EYE_X ROTATE_Y INTENSITY: the still scene of one pose
  cat <<S
{"image": {"width": 48, "height": 32},
 "camera": {"eye": [$1, 2, 5], "target": [0, 0.5, 0], "fov": 45},
 "render": {"algorithm": "${ALGORITHM:-zbuffer}"},
 "lights": [{"type": "ambient", "intensity": 0.2},
            {"type": "directional", "direction": [-0.5, -1, -0.4], "intensity": $3}],
 "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]},
             {"type": "box", "lo": [-0.5, 0, -0.5], "hi": [0.5, 1, 0.5],
              "transform": [{"translate": [0.25, 0, 0]}, {"rotate": $2}]}]
S
}
animated() {
  still 0 0 1
  cat <<S
 ,"animation": {"frames": 5, "keys": [
   {"frame": 0, "camera": {"eye": [-2, 2, 5]}, "objects": [{"object": 1, "rotate": [0, 0, 0]}],
    "lights": [{"light": 1, "intensity": 0.5}]},
   {"frame": 4, "camera": {"eye": [2, 2, 5]}, "objects": [{"object": 1, "rotate": [0, 90, 0]}],
    "lights": [{"light": 1, "intensity": 1.5}]}]}}
S
}
for ALGORITHM in zbuffer raytrace; do
  export ALGORITHM
  animated > "$tmp/anim.json"
  "$cg" render "$tmp/anim.json" --frames 0..4 -o "$tmp/f.png" 2>"$tmp/err" \
    || fail "$ALGORITHM: --frames 0..4: $(cat "$tmp/err")"
  for f in 0 1 2 3 4; do
    [ -f "$tmp/f-000$f.png" ] || fail "$ALGORITHM: frame $f not written as f-000$f.png"
  done
  cmp -s "$tmp/f-0000.png" "$tmp/f-0004.png" && fail "$ALGORITHM: frames 0 and 4 are the same"
  # frame k: eye x = -2 + k, the box turned by 22.5 k degrees after its own
  # placement, the light at 0.5 + 0.25 k
  for f in 0 2 3; do
    eye=$(awk -v k=$f 'BEGIN { print -2 + k }')
    turn=$(awk -v k=$f 'BEGIN { print 22.5 * k }')
    light=$(awk -v k=$f 'BEGIN { print 0.5 + 0.25 * k }')
    still "$eye" 0 "$light" | sed "s/{\"rotate\": 0}/{\"rotate\": 0}, {\"rotate\": $turn}/" > "$tmp/still.json"
    echo "}" >> "$tmp/still.json"
    "$cg" render "$tmp/still.json" -o "$tmp/still.png" 2>"$tmp/err" || fail "still $f: $(cat "$tmp/err")"
    cmp -s "$tmp/still.png" "$tmp/f-000$f.png" || fail "$ALGORITHM: frame $f differs from its still scene"
  done
done

# naming: %d and %0Nd take the number
ALGORITHM=zbuffer animated > "$tmp/anim.json"
"$cg" render "$tmp/anim.json" --frames 3..4 -o "$tmp/n%03d.png" 2>"$tmp/err" || fail "%03d: $(cat "$tmp/err")"
[ -f "$tmp/n003.png" ] && [ -f "$tmp/n004.png" ] && [ ! -f "$tmp/n002.png" ] || fail "%03d names: $(ls "$tmp")"
"$cg" render "$tmp/anim.json" --frames 3..3 -o "$tmp/m%d.png" 2>"$tmp/err" && [ -f "$tmp/m3.png" ] \
  || fail "%d names: $(ls "$tmp")"
cmp -s "$tmp/m3.png" "$tmp/n003.png" || fail "frame 3 differs between runs"

# errors: one line, non-zero, nothing written
expect_error() { # TEXT ARGS...
  local text=$1; shift
  if "$cg" "$@" > /dev/null 2>"$tmp/err"; then fail "accepted: $*"; return; fi
  grep -q -- "$text" "$tmp/err" || fail "$*: expected '$text', got: $(cat "$tmp/err")"
  [ "$(wc -l < "$tmp/err")" -eq 1 ] || fail "$*: more than one line: $(cat "$tmp/err")"
}
expect_error "animation has frames 0 to 4" render "$tmp/anim.json" --frames 3..5 -o "$tmp/bad.png"
expect_error "expected A..B" render "$tmp/anim.json" --frames 4..3 -o "$tmp/bad.png"
expect_error "expected A..B" render "$tmp/anim.json" --frames 2 -o "$tmp/bad.png"
expect_error "expected A..B" render "$tmp/anim.json" --frames a..b -o "$tmp/bad.png"
expect_error "the only % in OUT" render "$tmp/anim.json" --frames 0..1 -o "$tmp/bad%s.png"
expect_error "the only % in OUT" render "$tmp/anim.json" --frames 0..1 -o "$tmp/bad%d%d.png"
expect_error "animates a scene file" render "$src/examples/teaching/cube.obj" --frames 0..1 -o "$tmp/bad.png"
still 0 0 1 > "$tmp/still.json"; echo "}" >> "$tmp/still.json"
expect_error "no \"animation\" key" render "$tmp/still.json" --frames 0..1 -o "$tmp/bad.png"
ls "$tmp" | grep -q "^bad" && fail "an error wrote a file: $(ls "$tmp" | grep "^bad")"
# the example scene animates
"$cg" render "$src/examples/scenes/orbit.json" --frames 46..47 --size 64x48 -o "$tmp/orbit.png" 2>"$tmp/err" \
  && [ -f "$tmp/orbit-0047.png" ] || fail "orbit.json: $(cat "$tmp/err")"
[ $failed -eq 0 ] && echo "test_cmd_render_frames: all passed"
exit $failed

#!/usr/bin/env bash
# cg convert-mesh IN OUT: every format into every other, as a user meets it;
# what each carries survives (cg mesh info reads the result back), glTF in
# world space, and bad usage gets one clear line.
# Usage: test_cmd_convert_mesh.sh CG_BINARY SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
tmp=$(mktemp -d)
work="$tmp"
trap 'rm -rf "$tmp"' EXIT
. "$src/tests/cli_checks.sh"
# says DESCRIPTION TEXT: the last command's stderr holds TEXT
says() { grep -qF -- "$2" "$work/err" && pass || fail "$1: stderr lacks '$2': $(cat "$work/err")"; }

# A cube of 6 quads, 12 triangles once triangulated.
write_cube_obj "$tmp/cube.obj"
"$cg" mesh info "$tmp/cube.obj" > "$tmp/info.obj" 2>&1 || fail "mesh info cube.obj"

# every format into every other; the shape (vertices, closed, genus) stays
for out in obj ply off stl glb; do
  if "$cg" convert-mesh "$tmp/cube.obj" "$tmp/cube.$out" 2> "$tmp/err"; then pass
  else fail "convert-mesh cube.obj cube.$out: $(cat "$tmp/err")"; continue; fi
  for again in obj ply off stl glb; do
    "$cg" convert-mesh "$tmp/cube.$out" "$tmp/back_$out.$again" 2> "$tmp/err" \
      || { fail "convert-mesh cube.$out back_$out.$again: $(cat "$tmp/err")"; continue; }
    "$cg" mesh info "$tmp/back_$out.$again" > "$tmp/info" 2>&1
    for key in vertices closed genus components; do
      [ "$(value $key "$tmp/info")" = "$(value $key "$tmp/info.obj")" ] && pass \
        || fail "cube.obj -> .$out -> .$again: $key $(value $key "$tmp/info"), expected $(value $key "$tmp/info.obj")"
    done
  done
done
# triangulating formats count triangles: 12
for f in cube.stl cube.glb back_obj.glb back_glb.stl; do
  "$cg" mesh info "$tmp/$f" > "$tmp/info" 2>&1
  [ "$(value faces "$tmp/info")" = 12 ] && pass || fail "$f: faces $(value faces "$tmp/info"), expected 12"
done
[ "$(value faces "$tmp/info.obj")" = 6 ] && pass || fail "cube.obj: 6 faces expected"

# a glTF node transform is applied: the cube moved by (10, 0, 0) and scaled by 2
# the triangle (0 0 0) (1 0 0) (0 1 0) as 9 little-endian floats, base64
b64=AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA
cat > "$tmp/moved.gltf" <<EOT
{"asset": {"version": "2.0"},
 "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,$b64"}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "nodes": [{"mesh": 0, "translation": [10, 0, 0], "scale": [2, 2, 2]}]}
EOT
"$cg" convert-mesh "$tmp/moved.gltf" "$tmp/moved.obj" 2> "$tmp/err" && pass || fail "moved.gltf: $(cat "$tmp/err")"
grep -q "^v 12 0 0$" "$tmp/moved.obj" && grep -q "^v 10 2 0$" "$tmp/moved.obj" && pass \
  || fail "moved.obj: expected world-space vertices 12 0 0 and 10 2 0, got $(grep '^v' "$tmp/moved.obj" | tr '\n' ';')"

# bad usage and bad files: one line, nothing written
expect 2 "one file" "$cg" convert-mesh "$tmp/cube.obj"
one_line "one file"
says "one file" "expected IN and OUT files"
expect 2 "unknown output" "$cg" convert-mesh "$tmp/cube.obj" "$tmp/cube.xyz"
says "unknown output" "unknown output format"
expect 2 "bad format" "$cg" convert-mesh --format fbx "$tmp/cube.obj" "$tmp/cube.out"
one_line "bad format"
expect 1 "gltf text" "$cg" convert-mesh "$tmp/cube.obj" "$tmp/cube.gltf"
says "gltf text" "name it .glb"
[ -e "$tmp/cube.gltf" ] && fail "cube.gltf written" || pass
printf 'glTF\002\000\000\000\014\000\000\000' > "$tmp/short.glb"
expect 1 "short glb" "$cg" convert-mesh "$tmp/short.glb" "$tmp/out.obj"
one_line "short glb"
says "short glb" "short.glb: byte 12"
[ -e "$tmp/out.obj" ] && fail "out.obj written from a broken file" || pass
# --format overrides the extension
"$cg" convert-mesh --format stl "$tmp/cube.obj" "$tmp/cube.bin" && head -c 10 "$tmp/cube.bin" | grep -q "binary STL" \
  && pass || fail "--format stl"

finish

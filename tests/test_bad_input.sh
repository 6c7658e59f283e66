#!/usr/bin/env bash
# Bad input through the cg command as a user meets it: NaN and infinite
# vertex coordinates in every mesh format, negative PLY list lengths, formats
# cg does not read, and numbers beyond an integer's range in the other
# readers (scene files, draw scripts, WKT).  Each gets one clear line on
# stderr naming the file and where, a non-zero exit and no output file.
# Usage: test_bad_input.sh CG_BINARY SOURCE_DIR BUILD_DIR
set -u
cg="$1"
src="$2"
. "$src/tests/cli_checks.sh"
tmp="$work"

# says DESCRIPTION TEXT...: the last command's stderr contains each TEXT.
says() {
  local what=$1; shift
  for text in "$@"; do
    grep -qF -- "$text" "$work/err" && pass || fail "$what: no '$text' in: $(cat "$work/err")"
  done
}
# refused DESCRIPTION TEXT... -- COMMAND...: exit 1, one line, each TEXT, no out.png.
refused() {
  local what=$1; shift
  local texts=()
  while [ "$1" != "--" ]; do texts+=("$1"); shift; done
  shift
  rm -f "$tmp/out.png"
  expect 1 "$what" "$@"
  one_line "$what"
  says "$what" "${texts[@]}"
  [ -e "$tmp/out.png" ] && fail "$what: left an output file" || pass
}

# ---- NaN and infinite coordinates, every reader, every command that loads
printf 'v 0 0 0\nv 1 0 0\nv 0 1 nan\nf 1 2 3\n' > "$tmp/nan.obj"
printf 'OFF\n3 1 0\n0 0 0\ninf 0 0\n0 1 0\n3 0 1 2\n' > "$tmp/inf.off"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 -inf 0\n0 1 0\n3 0 1 2\n' > "$tmp/inf.ply"
printf 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 1e999\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n' > "$tmp/big.stl"
# binary STL: one triangle whose second corner has y = NaN (bytes 108..111)
{ printf 'binary stl'; head -c 70 /dev/zero; printf '\001\000\000\000'; head -c 24 /dev/zero
  printf '\000\000\200\077\000\000\300\177\000\000\000\000'; head -c 14 /dev/zero; } > "$tmp/nan.stl"
# binary PLY: vertex 1 has z = +inf
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
  head -c 12 /dev/zero; printf '\000\000\200\077\000\000\000\000\000\000\200\177'; head -c 12 /dev/zero
  printf '\003\000\000\000\000\001\000\000\000\002\000\000\000'; } > "$tmp/inf_bin.ply"
ply_body=$(( $(grep -abo 'end_header' "$tmp/inf_bin.ply" | cut -d: -f1) + 11 ))

for command in "mesh info" "render -o $tmp/out.png" "render --algorithm raytrace -o $tmp/out.png" \
               "trace-render -o $tmp/out.png" "mesh subdivide --loop 1"; do
  set -- $command
  out=()
  [ "$1" = mesh ] && [ "$2" = subdivide ] && out=("$tmp/out.obj")
  refused "$command nan.obj" "$tmp/nan.obj:3:" "got z = nan" -- "$cg" "$@" "$tmp/nan.obj" "${out[@]}"
  refused "$command inf.off" "$tmp/inf.off:4:" "got x = inf" -- "$cg" "$@" "$tmp/inf.off" "${out[@]}"
  refused "$command inf.ply" "$tmp/inf.ply:11:" "got y = -inf" -- "$cg" "$@" "$tmp/inf.ply" "${out[@]}"
  refused "$command big.stl" "$tmp/big.stl:5:" "got z = inf" -- "$cg" "$@" "$tmp/big.stl" "${out[@]}"
  refused "$command nan.stl" "$tmp/nan.stl: byte 108:" "got y = nan" "triangle 0, corner 1" \
    -- "$cg" "$@" "$tmp/nan.stl" "${out[@]}"
  refused "$command inf_bin.ply" "$tmp/inf_bin.ply: byte $((ply_body + 12)):" "got z = inf" \
    "vertex 1" -- "$cg" "$@" "$tmp/inf_bin.ply" "${out[@]}"
  [ -e "$tmp/out.obj" ] && fail "$command: left out.obj" || pass
done
# a scene's mesh: the scene's path, the key, then the mesh's message
printf '{"objects": [{"type": "mesh", "file": "nan.obj"}]}\n' > "$tmp/scene.json"
for command in render trace-render; do
  refused "$command scene" "$tmp/scene.json: objects[0].file: $tmp/nan.obj:3:" "got z = nan" \
    -- "$cg" $command "$tmp/scene.json" -o "$tmp/out.png"
done
# gzip is looked through: the same message
gzip -c "$tmp/nan.obj" > "$tmp/nan.obj.gz"
refused "nan.obj.gz" "$tmp/nan.obj.gz:3:" "got z = nan" -- "$cg" mesh info "$tmp/nan.obj.gz"

# ---- negative list lengths of a signed count type
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list char int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n' > "$tmp/neg.ply"
refused "list length -1" "$tmp/neg.ply:13: expected a list length of 0 or more in face 0, got -1" \
  -- "$cg" mesh info "$tmp/neg.ply"

# ---- glTF files that break the format are refused with the place and the reason
printf 'glTF\002\000\000\000\014\000\000\000' > "$tmp/short.glb"
refused "truncated glb" "$tmp/short.glb: byte 12: expected a 12-byte GLB header and a JSON chunk" \
  -- "$cg" mesh info "$tmp/short.glb"
printf '{"asset": {"version": "2.0"}, "scene": 0}\n' > "$tmp/noscene.gltf"
refused "gltf scene index" "$tmp/noscene.gltf: scene: expected an index into scenes" \
  -- "$cg" render "$tmp/noscene.gltf" -o "$tmp/out.png"

# ---- formats cg does not read, by content and by name
printf 'Kaydara FBX Binary  \000\032\000' > "$tmp/model.fbx"
printf '<?xml version="1.0"?>\n<COLLADA version="1.4.1"></COLLADA>\n' > "$tmp/model.dae"
printf 'BLENDER-v300' > "$tmp/model.blend"
printf 'v 0 0 0\n' > "$tmp/model.3ds"
for pair in "model.fbx:an FBX file (.fbx)" \
            "model.dae:a COLLADA file (.dae)" "model.blend:a Blender file (.blend)" \
            "model.3ds:a 3D Studio file (.3ds)"; do
  file=${pair%%:*} format=${pair#*:}
  refused "$file" "$tmp/$file:" "$format" "does not read" -- "$cg" mesh info "$tmp/$file"
  refused "render $file" "$tmp/$file:" "$format" -- "$cg" render "$tmp/$file" -o "$tmp/out.png"
done

finish

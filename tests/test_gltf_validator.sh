#!/usr/bin/env bash
# What cg writes as glTF, checked by the Khronos glTF validator (npm package
# gltf-validator, installed into tests/gltf by scripts/install-npm-deps.sh):
# cg convert-mesh writes .glb from OBJ (with and without materials, quads,
# normals, texture coordinates, PNG maps), PLY (vertex colours), an empty mesh, and
# every glTF 2.0 model of Debian's assimp-testmodels that cg reads (nodes,
# cameras, textured and PBR materials); the validator must report zero errors
# on each, and cg must read each back equal to what it wrote
# (tests/gltf_compare.c).  Skips only when node or the package is missing.
# usage: test_gltf_validator.sh CG SOURCE_DIR BUILD_DIR
set -u
cg="$1" source_dir=$(cd "$2" && pwd) build_dir="$3"
command -v node >/dev/null || { echo "test_gltf_validator: node not found: skipped (apt-get install nodejs npm)"; exit 77; }
module=""
for dir in "$source_dir/tests/gltf/node_modules" "$(npm root -g 2>/dev/null)"; do
  [ -n "$dir" ] && [ -f "$dir/gltf-validator/package.json" ] && module="$dir/gltf-validator" && break
done
[ -n "$module" ] || { echo "test_gltf_validator: the npm package gltf-validator not found: skipped (cd tests/gltf && npm install, or npm install -g gltf-validator@2.0.0-dev.3.10)"; exit 77; }
compare="$build_dir/tests/gltf_compare"
[ -x "$compare" ] || { echo "test_gltf_validator: $compare not built"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$source_dir/tests/cli_checks.sh"

# ---- the sources -------------------------------------------------------------
mkdir -p "$work/in" "$work/glb"
write_cube_obj "$work/in/cube.obj"
cat > "$work/in/materials.mtl" <<'EOT'
newmtl red plastic
Kd 0.8 0.1 0.1
Ks 0.5 0.5 0.5
Ns 64
newmtl glass
Kd 0.2 0.4 0.9
d 0.25
map_Kd -clamp on -s 2 2 1 logo.png
newmtl textured
Kd 1 1 1
map_Kd logo.png
newmtl lamp
Kd 1 1 1
Ke 4 3 1
EOT
cat > "$work/in/materials.obj" <<'EOT'
mtllib materials.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 2 2 2
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vt 0.25 0.75
vn 0 0 1
vn 0 0 2
vn 1 0 0
f 1/1/1 2/2/1 3/3/2 4/4/2
usemtl red plastic
f 1/1/1 2/2/1 6/3/3 5/4/3
usemtl glass
f 2/2/3 3/3/3 7/5/2
usemtl lamp
f 4/4/1 3/3/1 7/5/1
usemtl textured
f 1/1/1 3/3/1 7/5/1
usemtl red plastic
f 5/1/1 6/2/1 7/5/1
EOT
cat > "$work/in/colours.ply" <<'EOT'
ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
property uchar red
property uchar green
property uchar blue
element face 2
property list uchar int vertex_indices
end_header
0 0 0 255 0 0
1 0 0 0 255 0
1 1 0 0 0 255
0 1 0 255 255 255
3 0 1 2
3 0 2 3
EOT
printf 'v 0 0 0\nv 1 0 0\n' > "$work/in/empty.obj"
models=/usr/share/assimp/models/glTF2
# the texture: a PNG cg draws
printf 'size 16 16\nbackground white\ncolor #c03020\ndisc 8 8 5\n' > "$work/logo.draw"
"$cg" draw "$work/logo.draw" -o "$work/in/logo.png" 2> "$work/err" && pass || fail "cg draw logo.png: $(cat "$work/err")"
if [ -d "$models" ]; then
  find "$models" \( -name '*.gltf' -o -name '*.glb' \) -type f | LC_ALL=C sort > "$work/models"
else
  echo "test_gltf_validator: $models not found: only cg's own meshes (apt-get install assimp-testmodels)"
  : > "$work/models"
fi

# ---- convert, validate, read back ---------------------------------------------
i=0
list() { for f in "$work/in/"*.obj "$work/in/"*.ply; do echo "$f"; done; cat "$work/models"; }
while read -r file; do
  # the deliberately broken models (and those with nothing cg reads) stay out
  case "$file" in "$work/in/"*) ;; *) "$cg" mesh info "$file" > /dev/null 2>&1 || continue ;; esac
  name=$(basename "$file"); name="${name%.*}"
  out="$work/glb/$i-$name.glb"
  if "$cg" convert-mesh "$file" "$out" 2> "$work/err"; then pass
  else fail "convert-mesh $file: $(cat "$work/err")"; continue; fi
  echo "$file" >> "$work/sources"
  echo "$out" >> "$work/written"
  if "$compare" "$file" "$out" > "$work/cmp" 2>&1; then pass
  else fail "read back $file: $(cat "$work/cmp")"; fi
  i=$((i + 1))
done < <(list)
[ "$i" -ge 5 ] && pass || fail "only $i files written"
# a position beyond the range of floats is refused with a message, nothing written
printf 'v 0 0 0\nv 1e300 0 0\nv 0 1 0\nf 1 2 3\n' > "$work/huge.obj"
expect 1 "huge position" "$cg" convert-mesh "$work/huge.obj" "$work/huge.glb"
grep -q "beyond the range of floats" "$work/err" && pass || fail "huge position: $(cat "$work/err")"
[ -e "$work/huge.glb" ] && fail "huge.glb written" || pass
echo "test_gltf_validator: $i files written by cg"
CG_GLTF_VALIDATOR="$module" node "$source_dir/tests/gltf/validate.js" $(cat "$work/written") > "$work/report"
status=$?
sed "s|$work/glb/||" "$work/report"
[ $status = 0 ] && pass || fail "the validator reports errors (above)"
# each file reported, each with 0 errors
[ "$(grep -c ': 0 errors,' "$work/report")" = "$i" ] && pass \
  || fail "$(grep -c ': 0 errors,' "$work/report") of $i files free of errors"
finish

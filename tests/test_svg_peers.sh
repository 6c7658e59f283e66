#!/usr/bin/env bash
# cg svg against the renderers users know, on a fixed sample of the Papirus
# icon theme: 200 icons chosen deterministically (every k-th of the sorted
# distinct files of 64x64/), each rendered 64 px wide by cg, rsvg-convert
# and resvg.  cg's mean difference from resvg must be at most rsvg-convert's
# plus 0.5/255 on at least 99% of the icons (tests/svg_compare.c); the
# misses are listed.
# usage: test_svg_peers.sh CG SOURCE_DIR BUILD_DIR [SIZE [COUNT]]
set -u
cg="$1" source_dir=$(cd "$2" && pwd) build_dir="$3" size="${4:-64}" count="${5:-200}"
# CG_SVG_SAMPLE_DIR: another folder of SVG files (Adwaita's scalable/, say); CG_KEEP=1 keeps the renders
papirus=${CG_SVG_SAMPLE_DIR:-/usr/share/icons/Papirus/64x64}
[ -d "$papirus" ] || { echo "test_svg_peers: Papirus icons not found: skipped (apt-get install papirus-icon-theme)"; exit 77; }
command -v rsvg-convert >/dev/null || { echo "test_svg_peers: rsvg-convert not found: skipped (apt-get install librsvg2-bin)"; exit 77; }
command -v node >/dev/null || { echo "test_svg_peers: node not found: skipped (apt-get install nodejs npm)"; exit 77; }
# resvg: tests/svg/node_modules (npm install there) or a global install
module=""
for dir in "$source_dir/tests/svg/node_modules" "$(npm root -g 2>/dev/null)"; do
  [ -n "$dir" ] && [ -d "$dir/@resvg/resvg-js" ] && module="$dir/@resvg/resvg-js" && break
done
[ -n "$module" ] || { echo "test_svg_peers: the npm package @resvg/resvg-js not found: skipped (cd tests/svg && npm install, or npm install -g @resvg/resvg-js@2.6.2)"; exit 77; }
compare="$build_dir/tests/svg_compare"
[ -x "$compare" ] || { echo "test_svg_peers: $compare not built"; exit 1; }

work=$(mktemp -d)
trap '[ -n "${CG_KEEP:-}" ] || rm -rf "$work"' EXIT
mkdir -p "$work/cg" "$work/rsvg" "$work/resvg"
find -L "$papirus" -name '*.svg' -type f -print0 | xargs -0 realpath | LC_ALL=C sort -u >"$work/all"
total=$(wc -l <"$work/all")
step=$(( total / count )); [ "$step" -ge 1 ] || step=1
awk -v step="$step" -v count="$count" '(NR - 1) % step == 0 && n < count { print; n++ }' "$work/all" >"$work/list"
echo "test_svg_peers: $(wc -l <"$work/list") of $total Papirus icons, every ${step}th, at $size px"

i=0
while read -r file; do
  "$cg" svg "$file" -o "$work/cg/$i.png" --width "$size" 2>>"$work/cg.log" \
    || echo "cg svg failed on $file" >>"$work/failures"
  rsvg-convert -a -w "$size" "$file" -o "$work/rsvg/$i.png" 2>/dev/null || true
  i=$((i + 1))
done <"$work/list"
# resvg in one process; when it dies on a file (a panic aborts it), on after that file
first=0 listed=$(wc -l <"$work/list")
while [ "$first" -lt "$listed" ]; do
  CG_RESVG_MODULE="$module" node "$source_dir/tests/svg/resvg_render.js" "$size" "$work/resvg" \
    "$work/list" "$first" >>"$work/resvg.log" 2>&1 && break
  while [ "$first" -lt "$listed" ] && [ -f "$work/resvg/$first.png" ]; do first=$((first + 1)); done
  echo "test_svg_peers: resvg failed on $(sed -n "$((first + 1))p" "$work/list")"
  first=$((first + 1))
done
[ -f "$work/failures" ] && cat "$work/failures"
sort "$work/cg.log" | uniq -c | sort -rn | head -10 | sed 's/^/test_svg_peers: warnings: /'
"$compare" "$work/list" "$work/cg" "$work/rsvg" "$work/resvg" >"$work/result"
status=$?
grep -c '^ok' "$work/result" >/dev/null
grep '^MISS' "$work/result" | sed "s|$papirus/||"
tail -1 "$work/result"
exit $status

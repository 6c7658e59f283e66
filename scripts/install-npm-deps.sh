#!/usr/bin/env bash
# Installs the npm packages the tests need into their folders (resvg, for
# tests/test_svg_peers.sh and bench_svg, into tests/svg/node_modules; the
# Khronos glTF validator, for tests/test_gltf_validator.sh, into
# tests/gltf/node_modules), once: a folder whose packages are there is left
# alone.  Without npm, or without the registry, it says so and the tests that
# need them skip.
set -uo pipefail
cd "$(dirname "$0")/.."
for entry in tests/svg:@resvg/resvg-js tests/gltf:gltf-validator; do
  folder=${entry%%:*} package=${entry#*:}
  [ -d "$folder/node_modules/$package" ] && continue
  if ! command -v npm > /dev/null; then
    echo "install-npm-deps: npm not found: $folder's packages not installed (apt-get install npm)" >&2
    continue
  fi
  echo "install-npm-deps: npm install in $folder"
  npm install --prefix "$folder" --no-audit --no-fund --no-save > /dev/null \
    || echo "install-npm-deps: npm install in $folder failed: its tests will skip" >&2
done
exit 0

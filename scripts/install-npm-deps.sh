#!/usr/bin/env bash
# Installs the npm packages the tests need into their folders (today resvg,
# for tests/test_svg_peers.sh and bench_svg, into tests/svg/node_modules),
# once: a folder whose packages are there is left alone.  Without npm, or
# without the registry, it says so and the tests that need them skip.
set -uo pipefail
cd "$(dirname "$0")/.."
for folder in tests/svg; do
  [ -d "$folder/node_modules/@resvg/resvg-js" ] && continue
  if ! command -v npm > /dev/null; then
    echo "install-npm-deps: npm not found: $folder's packages not installed (apt-get install npm)" >&2
    continue
  fi
  echo "install-npm-deps: npm install in $folder"
  npm install --prefix "$folder" --no-audit --no-fund --no-save > /dev/null \
    || echo "install-npm-deps: npm install in $folder failed: its tests will skip" >&2
done
exit 0

#!/usr/bin/env bash
# Installs the Debian packages listed in deps/<group>*.txt for each group named
# on the command line (build, test, bench), when any is missing.  Needs root
# (or sudo); without either it lists what is missing and carries on.
set -euo pipefail
cd "$(dirname "$0")/.."

wanted=()
for group in "$@"; do
  for list in deps/"$group"*.txt; do
    [ -f "$list" ] || continue
    while read -r line; do
      line="${line%%#*}"
      for package in $line; do wanted+=("$package"); done
    done < "$list"
  done
done

missing=()
for package in "${wanted[@]}"; do
  # A Node.js from outside Debian (NodeSource's nodejs) bundles npm and conflicts
  # with Debian's npm package: any working npm will do.
  if [ "$package" = npm ] && command -v npm >/dev/null 2>&1; then continue; fi
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$package")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
  sudo=""
elif command -v sudo >/dev/null 2>&1; then
  sudo="sudo"
else
  echo "install-deps: not root and no sudo; please install: ${missing[*]}" >&2
  exit 0
fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"

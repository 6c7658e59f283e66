#!/usr/bin/env bash
# Checks cg's C files against .clang-format: names every file clang-format
# would change and exits 1 when there is one, 0 when all are formatted.
#   scripts/check-format.sh            every tracked .c and .h file
#   scripts/check-format.sh FILE...    only these
#   scripts/check-format.sh --count    also how many lines of each file (and
#                                      in all) formatting would change
# `clang-format -i FILE` formats a file.  Needs clang-format (Debian package
# clang-format, deps/test-rules.txt); exits 2 without it.
set -euo pipefail
cd "$(dirname "$0")/.."

count=0
if [ "${1:-}" = "--count" ]; then
  count=1
  shift
fi
if ! command -v clang-format > /dev/null; then
  echo "check-format: needs clang-format (Debian package clang-format)" >&2
  exit 2
fi
[ -f .clang-format ] || { echo "check-format: no .clang-format at $(pwd)" >&2; exit 2; }
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files '*.c' '*.h')
fi

unformatted=0
changed_lines=0
for file in "${files[@]}"; do
  if clang-format --style=file --dry-run --Werror "$file" > /dev/null 2>&1; then
    continue
  fi
  unformatted=$((unformatted + 1))
  if [ $count -eq 1 ]; then
    # lines of the file that formatting would replace or remove
    lines=$(clang-format --style=file "$file" | diff "$file" - | grep -c '^<' || true)
    changed_lines=$((changed_lines + lines))
    echo "$file: $lines lines"
  else
    echo "$file"
  fi
done

if [ $unformatted -gt 0 ]; then
  [ $count -eq 1 ] && echo "check-format: formatting would change $changed_lines lines" >&2
  echo "check-format: $unformatted of ${#files[@]} files are not formatted" \
       "(clang-format -i FILE formats one)" >&2
  exit 1
fi
echo "check-format: all ${#files[@]} files are formatted"

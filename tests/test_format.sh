#!/usr/bin/env bash
# Every tracked C file of cg is formatted as .clang-format says
# (scripts/check-format.sh names the ones that are not).
# Usage: test_format.sh CG SOURCE_DIR BUILD_DIR (the first and last unused).
set -uo pipefail
source_dir=$2
if ! command -v clang-format > /dev/null; then
  echo "test_format: clang-format not found: skipped (apt-get install clang-format)"
  exit 77
fi
if ! git -C "$source_dir" rev-parse --git-dir > /dev/null 2>&1; then
  echo "test_format: $source_dir is not a git checkout: skipped"
  exit 77
fi
"$source_dir/scripts/check-format.sh"

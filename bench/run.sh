#!/usr/bin/env bash
# bench/run.sh [BUILD [BENCH_NAME...]]
# Runs the built benchmarks (BUILD/bench/bench_*, or only the ones named, such
# as bench_fill) and rewrites bench/RESULTS.md with the table and a
# description of the machine.  Each program's rows are kept in
# BUILD/bench/rows/, so that rerunning one benchmark rebuilds the table with
# the last rows of the others.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
shift || true
kept="$build/bench/rows"
mkdir -p "$kept"
if [ $# -gt 0 ]; then
  programs=()
  for name in "$@"; do programs+=("$build/bench/$name"); done
else
  programs=("$build"/bench/bench_*)
  rm -f "$kept"/*.tsv
fi
for program in "${programs[@]}"; do
  [ -x "$program" ] && [ -f "$program" ] || { echo "bench: no program $program" >&2; continue; }
  name=$(basename "$program")
  echo "== $name" >&2
  "$program" | grep '^BENCH' > "$kept/$name.tsv.new" \
    && mv "$kept/$name.tsv.new" "$kept/$name.tsv" \
    || { rm -f "$kept/$name.tsv.new"; echo "bench: $name failed" >&2; }
done
rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
cat "$kept"/*.tsv > "$rows" 2>/dev/null || true

{
  echo "# Benchmark results"
  echo
  echo "Written by \`make bench\` on $(date -u '+%Y-%m-%d %H:%M UTC')."
  echo
  echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"\
       "$(nproc) cores, $(free -g | awk '/Mem:/{print $2}') GiB;"\
       "compiler $(cc --version | head -1)."
  echo "Times are medians of several runs on a shared machine; ratio = peer time / cg time"\
       "(above 1: cg is faster)."
  echo
  echo "| case | cg (ms) | peer | peer (ms) | ratio | note |"
  echo "|---|---:|---|---:|---:|---|"
  awk -F'\t' '{
      ratio = ($5 > 0 && $3 > 0) ? sprintf("%.2fx", $5 / $3) : "-";
      peer_ms = ($5 > 0) ? sprintf("%.3f", $5 * 1000) : "-";
      printf("| %s | %.3f | %s | %s | %s | %s |\n", $2, $3 * 1000, $4, peer_ms, ratio, $6);
    }' "$rows"
} > bench/RESULTS.md
cat bench/RESULTS.md

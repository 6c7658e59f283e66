#!/usr/bin/env bash
# Runs every built benchmark (BUILD/bench/bench_*) and rewrites
# bench/RESULTS.md with the table and a description of the machine.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
for program in "$build"/bench/bench_*; do
  [ -x "$program" ] || continue
  echo "== $(basename "$program")" >&2
  "$program" | grep '^BENCH' >> "$rows" || echo "bench: $(basename "$program") failed" >&2
done

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

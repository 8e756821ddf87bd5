#!/usr/bin/env bash
# What the mesher does with inexact predicates (CGAL::Simple_cartesian<double>)
# on the robustness catalogue and the real inputs of ../shared/data, next to
# Epick: builds benchmark/Advancing_front_mesh_2/inexact_kernel_report
# (Release, once as built and once with CGAL's assertions on) in
# build-benchmark/, runs both (each run in a child process with a time limit)
# and writes doc/Advancing_front_mesh_2/benchmark/inexact_kernel_report.md,
# which it also copies into the user manual between the lines
# <!-- BEGIN INEXACT KERNEL REPORT --> and <!-- END INEXACT KERNEL REPORT -->.
# About 3 minutes on 2 cores, build included.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
bash scripts/install-deps.sh
cmake -S . -B build-benchmark -DCMAKE_BUILD_TYPE=Release -DAFM_BUILD_BENCHMARKS=ON \
  -DAFM_BUILD_EXAMPLES=OFF -DAFM_BUILD_TESTS=OFF > /dev/null
cmake --build build-benchmark -j2 --target inexact_kernel_report inexact_kernel_report_assertions
data=../shared/data
[ -d "$data" ] || data=""
out=doc/Advancing_front_mesh_2/benchmark/inexact_kernel_report.md
mkdir -p "$(dirname "$out")"
{
  echo "Measured $(date -u +%Y-%m-%d) on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'),"
  echo "$(g++ --version | head -1), Release build."
  echo
  for report in inexact_kernel_report inexact_kernel_report_assertions; do
    build-benchmark/benchmark/Advancing_front_mesh_2/$report ${data:+--data "$data"} --time-limit 30
    echo
  done
} > "$out"
begin='<!-- BEGIN INEXACT KERNEL REPORT -->' end='<!-- END INEXACT KERNEL REPORT -->'
manual=doc/Advancing_front_mesh_2/Advancing_front_mesh_2.txt
if grep -qF "$begin" "$manual" && grep -qF "$end" "$manual"; then
  awk -v results="$out" -v begin="$begin" -v end="$end" '
    index($0, begin) > 0 { print; while((getline line < results) > 0) print line; skip = 1; next }
    index($0, end) > 0 { skip = 0 }
    !skip { print }' "$manual" > "$manual.tmp"
  cat "$manual.tmp" > "$manual"
  rm -f "$manual.tmp"
  echo "updated the report in $manual" >&2
fi
echo "wrote $out in $((SECONDS - start)) s" >&2

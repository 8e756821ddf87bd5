#!/usr/bin/env bash
# Builds Triangle 1.6 from ../shared/tools/triangle (a reference for the
# benchmarks only: its licence forbids shipping it, so nothing of it enters
# the repository) into DIR and prints the binary's path; prints nothing
# when the source is not there.
set -euo pipefail
dir=$1
if [ -f ../shared/tools/triangle/triangle.cpp ]; then
  mkdir -p "$dir"
  g++ -O3 -w -DLINUX -DANSI_DECLARATORS -o "$dir/triangle" ../shared/tools/triangle/triangle.cpp -lm
  echo "$dir/triangle"
fi

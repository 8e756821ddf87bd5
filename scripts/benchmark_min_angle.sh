#!/usr/bin/env bash
# The minimum angle bound (refine_to_minimum_angle_2, afmesh_2 --min-angle)
# side by side with CGAL Mesh_2 and Triangle 1.6 (-pq30Q, built from
# ../shared/tools/triangle when it is there; never shipped) at matched
# triangle counts, on the square with a hole and the four-element airfoil
# (both made by afm_make_input) at uniform sizes; then the termination sweep
# over 10,000 random domains (AFM_MIN_ANGLE_DOMAINS). Writes
# doc/Advancing_front_mesh_2/benchmark/min_angle_results.md.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
domains=${AFM_MIN_ANGLE_DOMAINS:-10000}
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DAFM_BUILD_BENCHMARKS=ON -DAFM_BUILD_TESTS=OFF > /dev/null
cmake --build build-release -j2 --target min_angle_comparison afm_make_input > /dev/null
bin=build-release/examples/Advancing_front_mesh_2
work=build-release/min_angle
mkdir -p "$work"
triangle=()
built=$(bash scripts/build_triangle.sh "$work")
[ -n "$built" ] && triangle=(--triangle "$built")
"$bin/afm_make_input" square-with-hole "$work/square_with_hole.poly"
"$bin/afm_make_input" multi-element-airfoil "$work/airfoil.poly"
bench=build-release/benchmark/Advancing_front_mesh_2/min_angle_comparison
out=doc/Advancing_front_mesh_2/benchmark/min_angle_results.md
mkdir -p "$(dirname "$out")"
{
  echo "# Minimum angle 30 degrees: ours, CGAL Mesh_2, Triangle 1.6"
  echo
  echo "Written by scripts/benchmark_min_angle.sh on $(nproc) cores, $(date -u +%Y-%m-%d)."
  echo "Ours and Mesh_2 timed in process (meshing only); Triangle as a whole process (reading and writing files)."
  echo
  "$bench" "$work/square_with_hole.poly" 0.005 30 "${triangle[@]}"
  "$bench" "$work/airfoil.poly" 0.05 30 "${triangle[@]}"
  echo "## The shared data"
  echo
  if [ -d ../shared/data ]; then "$bench" --shared ../shared/data 30; else echo "(../shared/data not found)"; fi
  echo "## Random domains"
  echo
  "$bench" --random "$domains" 30
} | tee "$out"

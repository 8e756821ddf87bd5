#!/usr/bin/env bash
# The main job: installs what is missing, builds the command-line tool
# (Release), generates the default input (a four-element airfoil from NACA
# formulas in a circular far field, made by our own code) and meshes it.
# Writes out/airfoil.poly, out/airfoil.off, out/airfoil.vtu, out/airfoil.svg
# and prints the statistics as JSON.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DAFM_BUILD_TESTS=OFF > /dev/null
cmake --build build/release -j2 --target afmesh_2 afm_make_input
mkdir -p out
B=build/release/examples/Advancing_front_mesh_2
"$B/afm_make_input" multi-element-airfoil out/airfoil.poly
"$B/afmesh_2" out/airfoil.poly --size "${AFM_DEMO_SIZE:-0.04}" \
  -o out/airfoil.off -o out/airfoil.vtu -o out/airfoil.svg --stats
echo "wrote out/airfoil.off, out/airfoil.vtu and out/airfoil.svg" >&2

#!/usr/bin/env bash
# The main job: installs what is missing, builds the command-line tool
# (Release), generates the default input (a four-element airfoil from NACA
# formulas in a circular far field, made by our own code) and meshes it with
# the size graded from the boundary spacing and five smoothing passes:
# out/airfoil.{off,vtu,msh,node,ele,edge}, the whole mesh coloured by
# quality (out/airfoil.svg) and a close-up of the elements
# (out/airfoil_closeup.svg). Prints a readable quality summary, then the
# statistics as JSON.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DAFM_BUILD_TESTS=OFF > /dev/null
cmake --build build/release -j2 --target afmesh_2 afm_make_input
mkdir -p out
B=build/release/examples/Advancing_front_mesh_2
"$B/afm_make_input" multi-element-airfoil out/airfoil.poly
"$B/afmesh_2" out/airfoil.poly --smooth 5 --svg-color quality --svg-window -0.25 -0.45 1.45 0.45 \
  -o out/airfoil_closeup.svg
"$B/afmesh_2" out/airfoil.poly --smooth 5 --svg-color quality \
  -o out/airfoil.off -o out/airfoil.vtu -o out/airfoil.msh -o out/airfoil.node -o out/airfoil.svg --report --stats
echo "wrote out/airfoil.{off,vtu,msh,node,ele,edge}, out/airfoil.svg (quality colours) and out/airfoil_closeup.svg" >&2

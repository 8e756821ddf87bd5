#!/usr/bin/env bash
# afmesh_2_mpi --min-angle 30 on 2 to 6 ranks against the serial mesh:
# the triangles left below the bound by the interfaces, on the four-element
# airfoil, the square with a hole (two boundary spacings), the MESH2D lake
# and a three-region input at 10 sizes (50 runs; about 3 minutes on 2 cores
# once built). Writes doc/Advancing_front_mesh_2/benchmark/mpi_min_angle.md.
# Usage: scripts/benchmark_mpi_min_angle.sh [REV]: with REV, the same runs
# of afmesh_2_mpi as it is at that commit, side by side.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh libopenmpi-dev openmpi-bin
source scripts/benchmark_common.sh
bench_build_tool
cmake --build build/release -j2 --target afmesh_2_mpi > /dev/null
g++ -O2 -std=c++17 -Itest/Advancing_front_mesh_2/include -Iinclude test/Advancing_front_mesh_2/afm_check_mesh.cpp \
  -o build/release/afm_check_mesh -lgmp -lmpfr
before=()
if [ $# -gt 0 ]; then
  before=(--before "$(bash scripts/build_at_commit.sh "$1" afmesh_2_mpi)/examples/Advancing_front_mesh_2/afmesh_2_mpi"
          "$(git rev-parse --short "$1")")
fi
lake=../shared/data/mesh2d/lake.msh
[ -f "$lake" ] || { echo "no $lake: the lake is left out" >&2; lake=""; }
/usr/bin/python3 benchmark/Advancing_front_mesh_2/mpi_min_angle_sweep.py "$B" build/release/afm_check_mesh \
  "${AFM_BENCH_DIR:-/tmp/afm_mpi_min_angle}" doc/Advancing_front_mesh_2/benchmark/mpi_min_angle.md "$lake" \
  "${before[@]}"

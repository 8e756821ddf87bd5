# Sourced by the benchmark scripts that run afmesh_2 itself: its Release
# build in build/release, and the inputs they share.

# Builds afmesh_2 and afm_make_input (Release, no tests); sets B to their
# directory.
bench_build_tool() {
  cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DAFM_BUILD_TESTS=OFF > /dev/null
  cmake --build build/release -j2 --target afmesh_2 afm_make_input > /dev/null
  B=build/release/examples/Advancing_front_mesh_2
}

# Writes the MESH2D lake from ../shared/data to the .poly file $1; fails,
# saying so, when the shared data is not there.
bench_make_lake() {
  local lake=../shared/data/mesh2d/lake.msh
  if [ ! -f "$lake" ]; then
    echo "no $lake: the lake is left out" >&2
    return 1
  fi
  "$B/afm_make_input" from-jigsaw "$1" "$lake" > /dev/null
}

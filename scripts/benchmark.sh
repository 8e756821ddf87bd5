#!/usr/bin/env bash
# The mesher comparison: installs what is missing (Gmsh's libgmsh-dev too),
# builds benchmark/Advancing_front_mesh_2/mesher_comparison (Release) in
# build-benchmark/, and runs our mesher, CGAL Mesh_2, Gmsh (Frontal-Delaunay
# and Delaunay) and CGAL's bulk Delaunay insertion on the same inputs at
# matched triangle counts. Writes doc/Advancing_front_mesh_2/benchmark/
# {benchmark_results.md, benchmark_time.svg, benchmark_memory.svg} (and PNGs
# when rsvg-convert is installed), then copies the results into README.md and
# the user manual between the lines <!-- BEGIN BENCHMARK RESULTS --> and
# <!-- END BENCHMARK RESULTS -->, where those lines exist. Then
# streaming_memory compares streaming with meshing in memory and Mesh_2
# (streaming_results.md in the same folder).
# About 9 minutes on 2 cores, build included (517 s on 2026-11-25). Arguments are passed on to
# mesher_comparison, e.g. --quick (a one-minute smoke run) or
# --max-triangles 1e6 (caps the square series, which runs up to 1e7).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
bash scripts/install-deps.sh libgmsh-dev

cmake -S . -B build-benchmark -DCMAKE_BUILD_TYPE=Release -DAFM_BUILD_BENCHMARKS=ON \
  -DAFM_BUILD_EXAMPLES=OFF -DAFM_BUILD_TESTS=OFF > /dev/null
cmake --build build-benchmark -j2 --target mesher_comparison streaming_memory
echo "built in $((SECONDS - start)) s" >&2

out=doc/Advancing_front_mesh_2/benchmark
mkdir -p "$out"
data=../shared/data
if [ ! -d "$data/mesh2d" ]; then
  echo "no $data/mesh2d: the MESH2D cases are skipped" >&2
  data=""
fi
build-benchmark/benchmark/Advancing_front_mesh_2/mesher_comparison --data "$data" --out "$out" "$@"
# streaming against meshing in memory and Mesh_2 (about 5 minutes)
streaming_sizes=1e5,1e6,1e7
case " $* " in *" --quick "*) streaming_sizes=1e4,1e5 ;; esac
build-benchmark/benchmark/Advancing_front_mesh_2/streaming_memory --sizes "$streaming_sizes" --out "$out" > /dev/null

# The results between the markers: without their title line, headings one
# level down (they sit in a section of their own), plot links relative to
# the repository root.
insert_results() {
  local file=$1 begin='<!-- BEGIN BENCHMARK RESULTS -->' end='<!-- END BENCHMARK RESULTS -->'
  [ -f "$file" ] || return 0
  if ! grep -qF "$begin" "$file" || ! grep -qF "$end" "$file"; then
    echo "$file has no benchmark markers: left unchanged" >&2
    return 0
  fi
  sed -e '1{/^# /d}' -e 's/^## /### /' \
      -e "s#(benchmark_\\(time\\|memory\\)\\.svg)#($out/benchmark_\\1.svg)#g" \
      "$out/benchmark_results.md" > "$file.results.tmp"
  awk -v results="$file.results.tmp" -v begin="$begin" -v end="$end" '
    index($0, begin) > 0 { print; while((getline line < results) > 0) print line; skip = 1; next }
    index($0, end) > 0 { skip = 0 }
    !skip { print }' "$file" > "$file.tmp"
  cat "$file.tmp" > "$file"
  rm -f "$file.tmp" "$file.results.tmp"
  echo "updated the benchmark results in $file" >&2
}
insert_results README.md
insert_results doc/Advancing_front_mesh_2/Advancing_front_mesh_2.txt

if command -v rsvg-convert > /dev/null; then
  for plot in benchmark_time benchmark_memory; do
    rsvg-convert -w 900 "$out/$plot.svg" -o "$out/$plot.png"
    # the user manual's figures (\cgalFigureBegin) are taken from fig/
    cp "$out/$plot.png" doc/Advancing_front_mesh_2/fig/
  done
else
  echo "rsvg-convert not installed: no PNG copies of the plots" >&2
fi
echo "wrote $out/benchmark_results.md, benchmark_time.svg, benchmark_memory.svg in $((SECONDS - start)) s" >&2

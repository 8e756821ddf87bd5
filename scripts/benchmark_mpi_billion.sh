#!/usr/bin/env bash
# One afmesh_2_mpi run of about 10^9 triangles on this machine, to disk:
# the square with a hole on AFM_BILLION_RANKS ranks (default 2, the cores
# here), each part meshed in streaming mode (--stream), binary pieces.
# Writes doc/Advancing_front_mesh_2/benchmark/mpi_billion.md: the time, each
# rank's peak memory and phases, the size of the pieces on disk, and the
# independent checker's verdict on windows cut out of the pieces
# (mpi_window_check): windows along the whole length of every interface
# (every triangle within about 46 sizes of the cut) and one window inside
# each rank's part. The pieces are deleted afterwards (AFM_BILLION_KEEP=1
# keeps them).
#
# AFM_BILLION_TRIANGLES (default 1e9) scales the run: 1e7 takes about 25 s,
# 1e9 about an hour. It needs about 65 bytes of disk per triangle in
# AFM_BENCH_DIR (default /tmp/afm_billion): the pieces (about 43) and the
# scratch files (about 20) until they are written.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh time libopenmpi-dev openmpi-bin
source scripts/benchmark_common.sh
bench_build_tool
cmake --build build/release -j2 --target afmesh_2_mpi > /dev/null
g++ -O2 -std=c++17 -Itest/Advancing_front_mesh_2/include -Iinclude test/Advancing_front_mesh_2/afm_check_mesh.cpp \
  -o build/release/afm_check_mesh -lgmp -lmpfr
g++ -O2 -std=c++17 benchmark/Advancing_front_mesh_2/mpi_window_check.cpp -o build/release/mpi_window_check
tools=build/release/examples/Advancing_front_mesh_2
work=${AFM_BENCH_DIR:-/tmp/afm_billion}
triangles=${AFM_BILLION_TRIANGLES:-1e9}
ranks=${AFM_BILLION_RANKS:-2}
out=${AFM_BILLION_REPORT:-doc/Advancing_front_mesh_2/benchmark/mpi_billion.md}
mkdir -p "$work"
rm -f "$work"/billion*.vtu "$work"/billion.pvtu "$work"/*.tmp "$work"/window*

# the square with a hole, boundary spacing 0.01; a uniform size of 0.000432
# gives 9.95e6 triangles, and the count goes about as the inverse square of
# it: 0.1% fewer at 1e9 (998,718,176 asked 1e9 this way), so the size aims
# 0.3% above the count asked, to reach it
"$tools/afm_make_input" square-with-hole "$work/square.poly" 0.01 > /dev/null
size=$(awk -v n="$triangles" 'BEGIN { printf "%.9g", 0.000432 * sqrt(9.95e6 / (1.003 * n)) }')
need_gb=$(awk -v n="$triangles" 'BEGIN { printf "%.0f", n * 65 / 1e9 + 1 }')
free_gb=$(df -P -BG "$work" | awk 'NR == 2 { sub("G", "", $4); print $4 }')
if [ "$free_gb" -lt "$need_gb" ]; then
  echo "benchmark_mpi_billion.sh: $work has ${free_gb} GB free, the run needs about ${need_gb} GB" >&2
  exit 1
fi

launcher=(mpirun --oversubscribe -np "$ranks")
[ "$(id -u)" -ne 0 ] || launcher+=(--allow-run-as-root)
export OMPI_MCA_btl_vader_single_copy_mechanism=none
echo "meshing about $triangles triangles (size $size) on $ranks ranks into $work ..."
/usr/bin/time -f "%e %M" -o "$work/time.txt" "${launcher[@]}" "$tools/afmesh_2_mpi" "$work/square.poly" \
  --size "$size" --stream -o "$work/billion.pvtu" --stats > "$work/stats.json"
read -r wall _ < "$work/time.txt"
disk_bytes=$(du -cb "$work"/billion*.vtu | tail -1 | cut -f1)

# the windows: along every cut, boxes 92 sizes wide and about 1,150 sizes
# long end to end over the domain; one box of about 650 sizes a side in
# the middle of each part, clear of the hole
windows=$(/usr/bin/python3 - "$work/stats.json" "$size" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
h = float(sys.argv[2])
axis, cuts = s["axis"], s["cuts"]
boxes = []
half, step = 46 * h, 1150 * h
for c in cuts:
    t = 0.0
    while t < 1.0:
        lo, hi = t, min(t + step, 1.0)
        boxes.append((c - half, lo, c + half, hi) if axis == 0 else (lo, c - half, hi, c + half))
        t = hi
bounds = [0.0] + list(cuts) + [1.0]
for r in range(len(bounds) - 1):
    mid, a = (bounds[r] + bounds[r + 1]) / 2, 325 * h
    centre = (mid, 0.12) if axis == 0 else (0.12, mid)
    boxes.append((centre[0] - a, centre[1] - a, centre[0] + a, centre[1] + a))
print(" ".join("%.17g" % v for b in boxes for v in b))
EOF
)
build/release/mpi_window_check "$work/billion.pvtu" "$work/square.poly" "$work/window" $windows > "$work/windows.txt"
n_cuts=$(/usr/bin/python3 -c "import json; print(len(json.load(open('$work/stats.json'))['cuts']))")
n_parts=$((n_cuts + 1))
n_boxes=$(wc -l < "$work/windows.txt")
checked=0
failed=0
checked_triangles=0
interface_triangles=0
rows=""
k=0
while read -r base nt _ nv _; do
  if [ "$nt" -eq 0 ]; then
    k=$((k + 1))
    continue # a box inside the hole
  fi
  verdict=$(build/release/afm_check_mesh "$base.poly" "$base.off" | tail -1) || failed=$((failed + 1))
  checked=$((checked + 1))
  checked_triangles=$((checked_triangles + nt))
  if [ $k -lt $((n_boxes - n_parts)) ]; then
    interface_triangles=$((interface_triangles + nt))
  else
    rows+="| part $((k - n_boxes + n_parts)) | $nt | $nv | ${verdict} |"$'\n'
  fi
  [ "${verdict:0:2}" = "ok" ] || echo "window $k: $verdict" >&2
  k=$((k + 1))
done < "$work/windows.txt"

today=$(date -u +%Y-%m-%d)
cores=$(nproc)
memory_gb=$(awk '/MemTotal/ { printf "%.0f", $2 / 1048576 }' /proc/meminfo)
/usr/bin/python3 - "$work/stats.json" "$wall" "$disk_bytes" "$size" "$ranks" > "$out.tmp" <<EOF
import json, sys
s = json.load(open(sys.argv[1]))
wall, disk, size, ranks = float(sys.argv[2]), int(sys.argv[3]), sys.argv[4], int(sys.argv[5])
print("# afmesh_2_mpi: one run of about $triangles triangles on this machine\n")
print("Generated by \`scripts/benchmark_mpi_billion.sh\` on $today (%d ranks of OpenMPI on" % ranks)
print("$cores cores, $memory_gb GB of memory). The square with a hole, boundary spacing 0.01,")
print("uniform size %s, each part meshed in streaming mode (\`--stream\`), binary pieces.\n" % size)
print("| triangles | vertices | wall time | triangles per second | pieces on disk | bytes per triangle |")
print("|--:|--:|--:|--:|--:|--:|")
n = s["number_of_faces"]
print("| %d | %d | %.0f s | %.0f | %.1f GB | %.1f |\n" % (n, s["number_of_vertices"], wall, n / wall, disk / 1e9, disk / n))
print("| rank | triangles | meshing | interfaces | writing | peak memory | held back near the cuts | band sent |")
print("|--:|--:|--:|--:|--:|--:|--:|--:|")
for r, p in enumerate(s["per_rank"]):
    print("| %d | %d | %.0f s | %.1f s | %.0f s | %.0f MB | %d triangles | %.1f MB |" % (
        r, p["triangles"], p["meshing_time"], p["interface_time"], p["writing_time"], p["peak_memory_mb"],
        p["held_triangles"], p["band_bytes_sent"] / 1e6))
print("\nThe cuts: %s (axis %d); band widenings %d, flips across the interfaces %d.\n" % (
    ", ".join("%.6f" % c for c in s["cuts"]), s["axis"], sum(p["band_widenings"] for p in s["per_rank"]),
    sum(p["interface_flips"] for p in s["per_rank"])))
EOF
{
  cat "$out.tmp"
  echo "The independent checker (\`afm_check_mesh\`, exact predicates: valid and constrained Delaunay) on windows"
  echo "cut out of the pieces by \`mpi_window_check\` (a window is the triangles with all three vertices in a box,"
  echo "checked against its own boundary): $checked windows, $checked_triangles triangles, $failed rejected."
  echo "Every interface ($n_cuts) along its whole length, every triangle within 46 sizes of the cut but those"
  echo "that straddle two boxes: $interface_triangles triangles. One window inside each rank's part:"
  echo
  echo "| window | triangles | vertices | checker |"
  echo "|---|--:|--:|---|"
  printf "%s" "$rows"
} > "$out"
rm -f "$out.tmp"
cat "$out"
if [ "${AFM_BILLION_KEEP:-0}" != 1 ]; then rm -f "$work"/billion*.vtu "$work"/window*; fi
[ "$failed" -eq 0 ]

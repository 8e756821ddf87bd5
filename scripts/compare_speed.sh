#!/usr/bin/env bash
# Meshing speed of two commits side by side: builds afmesh_2 (Release) at
# both, meshes the square with a hole at about 1M triangles (h = 0.001367)
# with each in turn, RUNS times (default 7), and prints the meshing times
# (the "mesh" time of --stats) and the ratio of the medians.
# Usage: scripts/compare_speed.sh BEFORE AFTER [RUNS] [H]; AFTER may be
# "worktree" for the uncommitted state.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: $0 BEFORE AFTER [RUNS] [H]" >&2; exit 1; }
before=$1 after=$2 runs=${3:-7} h=${4:-0.001367}
bash scripts/install-deps.sh
work=${AFM_COMPARE_DIR:-/tmp/afm_compare}
b1=$(bash scripts/build_at_commit.sh "$before" afmesh_2 afm_make_input)
b2=$(bash scripts/build_at_commit.sh "$after" afmesh_2 afm_make_input)
"$b1/examples/Advancing_front_mesh_2/afm_make_input" square-with-hole "$work/square.poly" "$h" > /dev/null
time_of() {
  "$1/examples/Advancing_front_mesh_2/afmesh_2" "$work/square.poly" --size "$h" -o "$work/speed.off" --stats |
    grep -o '"mesh": *[0-9.eE+-]*' | head -1 | sed 's/.*: *//'
}
t1=() t2=()
for ((i = 0; i < runs; i++)); do
  t1+=("$(time_of "$b1")")
  t2+=("$(time_of "$b2")")
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
m1=$(median "${t1[@]}") m2=$(median "${t2[@]}")
echo "$before: ${t1[*]} s (median $m1)"
echo "$after: ${t2[*]} s (median $m2)"
awk -v a="$m1" -v b="$m2" 'BEGIN {printf "median time ratio %s / %s: %.3f\n", ARGV[1], ARGV[2], b / a}' "$after" "$before"

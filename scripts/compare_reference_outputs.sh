#!/usr/bin/env bash
# Proves a refactoring a pure move: builds benchmark/Advancing_front_mesh_2/
# reference_outputs (Release) at two commits, runs each (OFF files, counters
# and checkpoint files of the test catalogue and the benchmark inputs, in the
# same directory so that paths stored in checkpoints agree) and compares the
# files byte for byte. Usage: scripts/compare_reference_outputs.sh BEFORE AFTER
# [--quick]; AFTER may be "worktree" for the uncommitted state. About 10
# minutes with the 1M-triangle square, 3 with --quick.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: $0 BEFORE AFTER [--quick]" >&2; exit 1; }
before=$1 after=$2
shift 2
bash scripts/install-deps.sh
root=$(pwd)
data=$(cd .. && pwd)/shared/data
[ -d "$data" ] || data=""
work=${AFM_REFERENCE_DIR:-/tmp/afm_reference}
mkdir -p "$work"
outputs() {
  local rev=$1 src
  if [ "$rev" = worktree ]; then
    src=$root
  else
    src=$work/src-$rev
    rm -rf "$src"
    git -C "$root" worktree add --force --detach "$src" "$rev" > /dev/null
  fi
  cmake -S "$src" -B "$work/build-$rev" -DCMAKE_BUILD_TYPE=Release -DAFM_BUILD_BENCHMARKS=ON \
    -DAFM_BUILD_TESTS=OFF -DAFM_BUILD_EXAMPLES=OFF > /dev/null
  cmake --build "$work/build-$rev" -j2 --target reference_outputs > /dev/null
  rm -rf "$work/run" "$work/out-$rev"
  mkdir -p "$work/run"
  (cd "$work/run" && "$work/build-$rev/benchmark/Advancing_front_mesh_2/reference_outputs" . $data "$@")
  mv "$work/run" "$work/out-$rev"
  if [ "$rev" != worktree ]; then git -C "$root" worktree remove --force "$src"; fi
}
outputs "$before" "$@"
outputs "$after" "$@"
files=$(ls "$work/out-$before" | wc -l)
if diff -r -q "$work/out-$before" "$work/out-$after"; then
  echo "identical: $files files ($(du -sh "$work/out-$after" | cut -f1)) of $before and $after"
else
  echo "the outputs of $before and $after differ" >&2
  exit 1
fi

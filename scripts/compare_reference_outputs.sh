#!/usr/bin/env bash
# Proves a refactoring a pure move: builds benchmark/Advancing_front_mesh_2/
# reference_outputs (Release) at two commits, runs each (OFF files, counters
# and checkpoint files of the test catalogue and the benchmark inputs, in the
# same directory so that paths stored in checkpoints agree) and compares the
# files byte for byte. Usage: scripts/compare_reference_outputs.sh BEFORE AFTER
# [--quick]; AFTER may be "worktree" for the uncommitted state. About 3
# minutes per commit to build, 15 s to run (--quick: without the 1M-triangle
# square).
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: $0 BEFORE AFTER [--quick]" >&2; exit 1; }
before=$1 after=$2
shift 2
bash scripts/install-deps.sh
data=$(cd .. && pwd)/shared/data
[ -d "$data" ] || data=""
work=${AFM_COMPARE_DIR:-/tmp/afm_compare}
outputs() {
  local rev=$1 build
  shift
  build=$(bash scripts/build_at_commit.sh "$rev" reference_outputs)
  rm -rf "$work/run" "$work/out-$rev"
  mkdir -p "$work/run"
  (cd "$work/run" && "$build/benchmark/Advancing_front_mesh_2/reference_outputs" . $data "$@" > /dev/null)
  mv "$work/run" "$work/out-$rev"
}
outputs "$before" "$@"
outputs "$after" "$@"
files=$(ls "$work/out-$before" | wc -l)
if diff -r -q "$work/out-$before" "$work/out-$after"; then
  echo "identical: $files files ($(du -sh "$work/out-$after" | cut -f1)) written by $before and by $after"
else
  echo "the outputs of $before and $after differ" >&2
  exit 1
fi

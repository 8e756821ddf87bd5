#!/usr/bin/env bash
# Builds targets of the project as it is at a commit (Release, benchmarks on,
# in a worktree under $AFM_COMPARE_DIR, default /tmp/afm_compare) and prints
# the build directory. REV "worktree" builds the checkout as it is.
# Usage: scripts/build_at_commit.sh REV TARGET... (used by the compare_* scripts)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
rev=$1
shift
work=${AFM_COMPARE_DIR:-/tmp/afm_compare}
mkdir -p "$work"
if [ "$rev" = worktree ]; then
  src=$root
else
  commit=$(git -C "$root" rev-parse --verify "$rev^{commit}")
  src=$work/src-$commit
  if [ ! -d "$src" ]; then
    git -C "$root" worktree add --force --detach "$src" "$commit" > /dev/null 2>&1
  fi
  rev=$commit
fi
cmake -S "$src" -B "$work/build-$rev" -DCMAKE_BUILD_TYPE=Release -DAFM_BUILD_BENCHMARKS=ON \
  -DAFM_BUILD_TESTS=OFF > /dev/null
cmake --build "$work/build-$rev" -j2 --target "$@" > /dev/null
echo "$work/build-$rev"

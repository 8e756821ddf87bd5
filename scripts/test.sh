#!/usr/bin/env bash
# The whole test suite: installs what is missing, then builds and runs every
# test twice: in a Debug build with CGAL's assertions on, and in a Debug
# build under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=${AFM_JOBS:-2}
for variant in debug asan; do
  sanitize=OFF
  [ "$variant" = asan ] && sanitize=ON
  echo "=== $variant build ==="
  cmake -S . -B "build/$variant" -DCMAKE_BUILD_TYPE=Debug -DAFM_SANITIZE=$sanitize > /dev/null
  cmake --build "build/$variant" -j"$jobs"
  echo "=== $variant tests ==="
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "build/$variant" --output-on-failure -j"$jobs" --timeout 1500
done

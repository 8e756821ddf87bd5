#!/usr/bin/env bash
# The whole test suite: installs what is missing, then builds and runs every
# test twice: in a Debug build with CGAL's assertions on, and in a Debug
# build under AddressSanitizer + UndefinedBehaviorSanitizer; then builds the
# libFuzzer targets with clang and runs each for AFM_FUZZ_SECONDS (default
# 60) from its corpus. Two kinds of tests run in one build only, to keep
# the run within CI's time: the threaded tests also run under
# ThreadSanitizer (a third build of their executable alone); the mesher's tests with the other search
# structures (Kd_tree, brute force) in the sanitizer build, which is also a
# Debug build with CGAL's assertions on, and the consumer project of the
# installed package (a build test) and the threaded tests compiled with -O2
# -DNDEBUG (as users build) in the plain Debug build.
set -euo pipefail
cd "$(dirname "$0")/.."
# GDAL (libgdal-dev, and gdal-bin's ogr2ogr to make test inputs) is optional for users; the tests install it
# so that the OGR inputs are tested (scripts/demo.sh does without it)
bash scripts/install-deps.sh clang libclang-rt-14-dev python3-meshio python3-gmsh pybind11-dev python3-numpy \
  python3-pytest libgdal-dev gdal-bin
jobs=${AFM_JOBS:-2}
for variant in debug asan; do
  sanitize=OFF models=OFF package=ON optimised=ON
  [ "$variant" = asan ] && sanitize=ON models=ON package=OFF optimised=OFF
  echo "=== $variant build ==="
  cmake -S . -B "build/$variant" -DCMAKE_BUILD_TYPE=Debug -DAFM_SANITIZE=$sanitize \
    -DAFM_TEST_SEARCH_MODELS=$models -DAFM_TEST_PACKAGE=$package -DAFM_TEST_OPTIMISED=$optimised > /dev/null
  cmake --build "build/$variant" -j"$jobs"
  echo "=== $variant tests ==="
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "build/$variant" --output-on-failure -j"$jobs" --timeout 1500
done

# The threaded tests once more under ThreadSanitizer (only their executable
# is built; the parts run on std::threads there, see mesh_in_parallel_2.h)
echo "=== tsan build (the threaded tests) ==="
cmake -S . -B build/tsan -DCMAKE_BUILD_TYPE=Debug -DAFM_SANITIZE_THREAD=ON -DAFM_BUILD_EXAMPLES=OFF -DAFM_TEST_OPTIMISED=OFF \
  -DAFM_TEST_SEARCH_MODELS=OFF -DAFM_TEST_PACKAGE=OFF > /dev/null
cmake --build build/tsan -j"$jobs" --target test_parallel_meshing
echo "=== tsan tests ==="
TSAN_OPTIONS=halt_on_error=1 ctest --test-dir build/tsan --output-on-failure -j"$jobs" --timeout 1500 -R '^test_parallel_'

fuzz_seconds=${AFM_FUZZ_SECONDS:-60}
echo "=== fuzz build (clang, libFuzzer + ASan + UBSan) ==="
cmake -S . -B build/fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DAFM_BUILD_FUZZERS=ON -DAFM_BUILD_TESTS=OFF -DAFM_BUILD_EXAMPLES=OFF > /dev/null
cmake --build build/fuzz -j"$jobs"
for target in read_poly mesh; do
  echo "=== fuzz_$target: $fuzz_seconds s ==="
  # a scratch copy of the corpus: what the fuzzer adds stays out of the repository
  corpus="build/fuzz/corpus_$target"
  rm -rf "$corpus"
  mkdir -p "$corpus"
  cp test/Advancing_front_mesh_2/fuzz/corpus/$target/* "$corpus"/
  build/fuzz/test/Advancing_front_mesh_2/fuzz/fuzz_$target -max_total_time="$fuzz_seconds" -timeout=30 \
    -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix=build/fuzz/ "$corpus"
done

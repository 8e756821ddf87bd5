#!/usr/bin/env bash
# The whole test suite: installs what is missing, then builds every test once
# in a Debug build with CGAL's assertions on, under AddressSanitizer +
# UndefinedBehaviorSanitizer, and runs it; builds the threaded tests once more
# under ThreadSanitizer and runs them; then builds the libFuzzer targets with
# clang and runs each for AFM_FUZZ_SECONDS (default 60) from its corpus.
# The one Debug build also holds the mesher's tests with the other search
# structures (Kd_tree, brute force), the consumer project of the installed
# package (a build test) and the threaded tests compiled with -O2 -DNDEBUG
# and no sanitizer (as users build them). A plain Debug build beside the
# sanitizer one would run the same assertions again for a third of the run's
# time (it did until the run reached 88 minutes of CI's 90).
set -euo pipefail
cd "$(dirname "$0")/.."
stage_start=$SECONDS
stage_times=""
end_stage() { stage_times+="$(printf '%-28s %5d s' "$1" $((SECONDS - stage_start)))"$'\n'; stage_start=$SECONDS; }
report_stage_times() { printf '=== time per stage ===\n%s' "$stage_times"; }
trap report_stage_times EXIT

# GDAL (libgdal-dev, and gdal-bin's ogr2ogr to make test inputs) is optional for users; the tests install it
# so that the OGR inputs are tested (scripts/demo.sh does without it); OpenMPI likewise, for afmesh_2_mpi
bash scripts/install-deps.sh clang libclang-rt-14-dev python3-meshio python3-gmsh pybind11-dev python3-numpy \
  python3-pytest libgdal-dev gdal-bin libopenmpi-dev openmpi-bin
end_stage "installing what is missing"
jobs=${AFM_JOBS:-2}
# Line tables only (-g1) instead of full debug information: the sanitizers'
# reports keep their files and lines, and the compiler does a third less work
# (test_validity_checker.cpp under ASan: 92 s -> 57 s; objects half the size)
debug_info=-DCMAKE_CXX_FLAGS_DEBUG=-g1
echo "=== Debug build (CGAL assertions, ASan + UBSan) ==="
cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=Debug "$debug_info" -DAFM_SANITIZE=ON -DAFM_TEST_SEARCH_MODELS=ON \
  -DAFM_TEST_PACKAGE=ON -DAFM_TEST_OPTIMISED=ON > /dev/null
cmake --build build/asan -j"$jobs"
end_stage "Debug + ASan build"
echo "=== Debug tests (CGAL assertions, ASan + UBSan) ==="
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build/asan --output-on-failure -j"$jobs" --timeout 1500
end_stage "Debug + ASan tests"

# The threaded tests once more under ThreadSanitizer (only their executable
# is built; the parts run on std::threads there, see mesh_in_parallel_2.h)
echo "=== tsan build (the threaded tests) ==="
cmake -S . -B build/tsan -DCMAKE_BUILD_TYPE=Debug "$debug_info" -DAFM_SANITIZE_THREAD=ON -DAFM_BUILD_EXAMPLES=OFF -DAFM_TEST_OPTIMISED=OFF \
  -DAFM_TEST_SEARCH_MODELS=OFF -DAFM_TEST_PACKAGE=OFF > /dev/null
cmake --build build/tsan -j"$jobs" --target test_parallel_meshing
echo "=== tsan tests ==="
TSAN_OPTIONS=halt_on_error=1 ctest --test-dir build/tsan --output-on-failure -j"$jobs" --timeout 1500 -R '^test_parallel_'
end_stage "TSan build and tests"

fuzz_seconds=${AFM_FUZZ_SECONDS:-60}
echo "=== fuzz build (clang, libFuzzer + ASan + UBSan) ==="
cmake -S . -B build/fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DAFM_BUILD_FUZZERS=ON -DAFM_BUILD_TESTS=OFF -DAFM_BUILD_EXAMPLES=OFF > /dev/null
cmake --build build/fuzz -j"$jobs"
end_stage "fuzz build"
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
end_stage "fuzzing"

#!/usr/bin/env bash
# The second CI configuration: the whole test suite (GoogleTest and app tests) built with clang,
# AddressSanitizer (LeakSanitizer on) and UndefinedBehaviorSanitizer; any finding fails the run.
# The same instrumented build holds the libFuzzer targets, which scripts/fuzz.sh then runs.
# Run after scripts/test.sh (which installs the packages, clang included). The bench is not built
# (nothing tests it), and downstream_find_package is left out: a downstream build without the
# sanitizer flags cannot link an instrumented library; scripts/test.sh tests the packaging.
set -euo pipefail
cd "$(dirname "$0")/.."
CC=clang CXX=clang++ cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release \
  -DPCL_TENSOR_BUILD_FUZZERS=ON -DPCL_TENSOR_BUILD_BENCH=OFF > /dev/null
cmake --build build-sanitize -j2
source scripts/sanitizer_env.sh
cd build-sanitize
ctest -j2 --output-on-failure --timeout 1800 -E '^downstream_find_package$'

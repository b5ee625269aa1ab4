#!/usr/bin/env bash
# The second CI configuration: the whole test suite (library, GoogleTest and app tests) built with
# AddressSanitizer (LeakSanitizer on) and UndefinedBehaviorSanitizer; any finding fails the run.
# Run after scripts/test.sh, which installs the packages. The bench is not built (nothing tests it),
# and downstream_find_package is left out: a downstream build without the sanitizer flags cannot
# link an instrumented library, and packaging is tested by scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release -DPCL_TENSOR_BUILD_BENCH=OFF \
  -DCMAKE_C_FLAGS="$SAN" -DCMAKE_CXX_FLAGS="$SAN" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build build-sanitize -j2
SUPP="$PWD/test/sanitizers"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:check_initialization_order=1:strict_init_order=1"
export LSAN_OPTIONS="suppressions=$SUPP/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=$SUPP/ubsan.supp:print_stacktrace=1:halt_on_error=1"
cd build-sanitize
ctest -j2 --output-on-failure --timeout 1800 -E '^downstream_find_package$'

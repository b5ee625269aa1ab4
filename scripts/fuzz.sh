#!/usr/bin/env bash
# Run each libFuzzer target (clang, AddressSanitizer and UndefinedBehaviorSanitizer on) for
# FUZZ_SECONDS (default 60) from its seed corpus in test/fuzz/corpus; any crash, leak, sanitizer
# finding or time-out fails. Run after scripts/setup.sh (clang, libclang-rt-14-dev).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${FUZZ_SECONDS:-60}
# The instrumented build of scripts/test_sanitizers.sh, or a new one with the fuzz targets only.
if [ ! -f build-sanitize/CMakeCache.txt ]; then
  CC=clang CXX=clang++ cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release -DPCL_TENSOR_BUILD_FUZZERS=ON \
    -DBUILD_TESTING=OFF -DPCL_TENSOR_BUILD_APPS=OFF -DPCL_TENSOR_BUILD_BENCH=OFF > /dev/null
fi
TARGETS="stanford_conf range_scan mesh_tensors"
cmake --build build-sanitize -j2 --target $(for t in $TARGETS; do echo fuzz_$t; done)
source scripts/sanitizer_env.sh
for t in $TARGETS; do
  # Findings go to build-sanitize/findings/<target>; the committed seed corpus is only read.
  work="build-sanitize/corpus/$t"; findings="build-sanitize/findings/$t"
  mkdir -p "$work" "$findings"
  echo "== fuzz_$t for ${SECONDS_EACH} s"
  log="build-sanitize/fuzz_$t.log"
  if ! ./build-sanitize/test/fuzz/fuzz_$t "$work" "test/fuzz/corpus/$t" -max_total_time="$SECONDS_EACH" \
       -seed=2006 -max_len=4096 -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$findings/" -print_final_stats=1 > "$log" 2>&1; then
    tail -n 60 "$log"
    echo "fuzz_$t found a problem: the input is in $findings"
    exit 1
  fi
  grep -E "^(Done|stat::number_of_executed_units|stat::peak_rss_mb)" "$log" || tail -n 5 "$log"
done
echo "fuzzing: no finding"

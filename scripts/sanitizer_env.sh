# Sourced by scripts/test_sanitizers.sh and scripts/fuzz.sh: every finding is fatal, leaks included.
SANITIZER_SUPPRESSIONS="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/test/sanitizers"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$SANITIZER_SUPPRESSIONS/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=$SANITIZER_SUPPRESSIONS/ubsan.supp:print_stacktrace=1:halt_on_error=1"

#!/usr/bin/env bash
# Set up, build and run the whole test suite (the README's second command; CI runs it too).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
cd build && ctest -j2 --output-on-failure --timeout 900

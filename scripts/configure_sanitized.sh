#!/usr/bin/env bash
# Configures a clang build folder for the sanitizer and fuzz jobs:
#   scripts/configure_sanitized.sh DIR DEBUG_FLAG [cmake options]
# -O1 keeps the instrumented tests fast enough for CI while reports stay readable. DEBUG_FLAG:
# -g1 (line tables: file:line in reports, cheap to compile) or -g (also qualified names of
# inlined functions, which the ThreadSanitizer suppressions match on). Asserts stay on (no
# NDEBUG): an instrumented build should also check the code's own invariants.
set -euo pipefail
cd "$(dirname "$0")/.."
dir="$1"
debug_flag="$2"
shift 2
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
      -DCMAKE_CXX_FLAGS_RELEASE="-O1 $debug_flag" "$@" > /dev/null

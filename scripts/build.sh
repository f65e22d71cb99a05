#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds ontile (Release) into build/.
# Arguments name the targets to build (e.g. `ontile`); none builds everything (tests, benchmarks).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j "$(nproc)" "${targets[@]}"

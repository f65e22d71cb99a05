#!/usr/bin/env bash
# Builds ontile and its llvmpipe peer (installing missing Debian packages first) and runs the
# comparison benchmark: ontile's lambert and cartoon frames against Mesa llvmpipe at 1920x1080,
# 1 and 2 threads. Arguments go to build/ontile_peer_bench (e.g. --frames 9 --scenes
# atrium,ToyCar --pipelines cartoon); the tables are also written to out/peer_bench.md.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j "$(nproc)" --target ontile_peer_bench ontile_llvmpipe
mkdir -p out
build/ontile_peer_bench --markdown out/peer_bench.md "$@"

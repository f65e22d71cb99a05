#!/usr/bin/env bash
# Reproduces the bandwidth tables of docs/deferred.md: builds ontile, generates the atrium and
# runs `ontile study deferred` (2220x1080, 16x16 tiles, 128-bit budget, 48 lights by default;
# extra arguments are passed on, e.g. --size 1920x1080 --lights 256 --frames 3).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out  # the CLI never creates folders for its outputs
build/ontile gen-scene atrium --out out/atrium.glb
build/ontile study deferred --scene out/atrium.glb --markdown out/deferred_study.md "$@"

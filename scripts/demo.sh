#!/usr/bin/env bash
# Builds ontile and renders the bundled demo scene with the cartoon pipeline to out/demo.png,
# printing the summary and the traffic report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
build/ontile render --scene scenes/demo.glb --pipeline "${ONTILE_DEMO_PIPELINE:-cartoon}" \
  --size 1280x720 --out out/demo.png --report out/demo.json

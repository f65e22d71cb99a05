#!/usr/bin/env bash
# Builds the ontile CLI alone (not the tests: the first image comes after one target's build) and
# renders the bundled demo scene with the cartoon pipeline to out/demo.png (with out/demo.json and
# the HTML report out/demo.html), printing the summary and the traffic report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh ontile
# The CLI never creates folders for its outputs; the demo's folder is made here.
mkdir -p out
build/ontile render --scene scenes/demo.glb --pipeline "${ONTILE_DEMO_PIPELINE:-cartoon}" \
  --size 1280x720 --out out/demo.png --report out/demo.json --html out/demo.html

#!/usr/bin/env bash
# Installs ontile's build dependencies from Debian packages when any is missing (needs root
# or sudo). Safe to run repeatedly: it does nothing when everything is present.
set -euo pipefail
packages=(build-essential cmake libglm-dev libembree-dev libopenimageio-dev libtbb-dev
          libtinygltf-dev libgtest-dev libbenchmark-dev nlohmann-json3-dev libcli11-dev
          libstb-dev openimageio-tools libhwy-dev zlib1g-dev
          libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
          python3 python3-jsonschema chromium
          pybind11-dev python3-dev python3-numpy python3-distributed)
# zlib1g-dev: crc32 for transaction elimination (OpenImageIO pulls it in too).
# openimageio-tools: Debian's OpenImageIO CMake config references its command-line tools.
# libegl-dev, libgles-dev, libegl-mesa0, libgl1-mesa-dri: EGL/GLES headers and Mesa's llvmpipe
# for the peer benchmark (bench/llvmpipe/, scripts/peer_bench.sh).
# python3-jsonschema: the tests check every render report against docs/report.schema.json.
# pybind11-dev, python3-dev, python3-numpy, python3-distributed: the `ontile` Python module, its
# NumPy images and sweeps on Dask (docs/python.md, docs/scaling.md).
# chromium: the browser test opens `render --html` pages headless (HtmlBrowser.*; skipped without it).
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

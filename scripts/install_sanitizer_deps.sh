#!/usr/bin/env bash
# Installs what the sanitizer and fuzz jobs need on top of scripts/install_deps.sh, when
# missing (root or sudo): clang 14, its runtime libraries (AddressSanitizer, UBSan,
# ThreadSanitizer, libFuzzer: libclang-rt-14-dev, only "recommended" by clang) and
# llvm-symbolizer (llvm-14) for file:line in sanitizer reports.
set -euo pipefail
packages=(clang libclang-rt-14-dev llvm-14)
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

#!/usr/bin/env bash
# CI's fuzz smoke run (docs/robustness.md, "Fuzzing"): builds the libFuzzer targets of fuzz/
# (AddressSanitizer + UBSan + LeakSanitizer, in build-asan/, shared with scripts/sanitize.sh),
# makes the seed corpus and runs each target for a bounded time. Any crash, sanitizer report,
# leak, timeout (one input over 10 s) or out-of-memory (over 2 GiB) fails the run; the input
# that caused it is saved as build-asan/fuzz/artifacts/TARGET-crash-... (or leak-, timeout-,
# oom-) and can be replayed with build-asan/fuzz/TARGET FILE.
# Usage: scripts/fuzz_smoke.sh [SECONDS_PER_TARGET (default 60)] [TARGET...]
set -euo pipefail
export LC_ALL=C  # byte lengths in make_glb
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(gltf_fuzzer glb_fuzzer set_options_fuzzer)
bash scripts/install_deps.sh
bash scripts/install_sanitizer_deps.sh
source sanitizers/env.sh
build=build-asan
bash scripts/configure_sanitized.sh "$build" -g1 -DONTILE_SANITIZERS=address,undefined -DONTILE_BUILD_FUZZERS=ON
cmake --build "$build" -j "$(nproc)" --target ontile "${targets[@]}"

# Seeds: the hand-written text seeds of fuzz/corpus/, the bundled scene, the generator's
# scenes (the smallest atrium, 2 MB: -max_len below keeps it whole), JSON-only GLB copies of the .gltf seeds, a GLB with a BIN chunk
# from fuzz/corpus/glb/, and the third-party .glb models of ../shared/assets when present.
seeds="$build/fuzz/seeds"
rm -rf "$seeds"
mkdir -p "$seeds/gltf" "$seeds/glb" "$seeds/set_options" "$build/fuzz/artifacts"
cp fuzz/corpus/gltf/*.gltf "$seeds/gltf/"
cp fuzz/corpus/set_options/*.txt "$seeds/set_options/"
cp scenes/demo.glb "$seeds/glb/bundled_demo.glb"
"$build/ontile" gen-scene atrium --size 0.05 --out "$seeds/glb/atrium_0.05.glb" > /dev/null
if [ -d ../shared/assets ]; then
  find ../shared/assets -name '*.glb' -size -512k -exec cp {} "$seeds/glb/" \;
fi

# Writes the 32-bit little-endian value $1 as four bytes.
le32() { printf "\\x$(printf %02x $(($1 & 255)))\\x$(printf %02x $(($1 >> 8 & 255)))\\x$(printf %02x $(($1 >> 16 & 255)))\\x$(printf %02x $(($1 >> 24 & 255)))"; }
# make_glb JSON_FILE [BIN_FILE] > OUT: a GLB 2.0 container (glTF 2.0 spec 4.4): the header, the
# JSON chunk padded with spaces and the optional BIN chunk padded with zeros to 4 bytes.
make_glb() {
  local json bin="" json_pad bin_pad total
  json="$(cat "$1")"
  json_pad=$(( (4 - ${#json} % 4) % 4 ))
  total=$(( 12 + 8 + ${#json} + json_pad ))
  if [ $# -gt 1 ]; then
    bin="$(cat "$2")"  # hex text
    bin_pad=$(( (4 - ${#bin} / 2 % 4) % 4 ))
    total=$(( total + 8 + ${#bin} / 2 + bin_pad ))
  fi
  printf 'glTF'; le32 2; le32 "$total"
  le32 $(( ${#json} + json_pad )); printf 'JSON'; printf '%s' "$json"; printf '%*s' "$json_pad" ''
  if [ -n "$bin" ]; then
    le32 $(( ${#bin} / 2 + bin_pad )); printf 'BIN\0'
    printf "$(printf '%s' "$bin" | sed 's/../\\x&/g')"
    for ((i = 0; i < bin_pad; i++)); do printf '\0'; done
  fi
}
for seed in fuzz/corpus/gltf/*.gltf; do
  make_glb "$seed" > "$seeds/glb/$(basename "$seed" .gltf).glb"
done
for json in fuzz/corpus/glb/*.json; do
  make_glb "$json" "${json%.json}.bin.hex" > "$seeds/glb/$(basename "$json" .json).glb"
done

declare -A seed_folder=([gltf_fuzzer]=gltf [glb_fuzzer]=glb [set_options_fuzzer]=set_options)
declare -A dictionary=([gltf_fuzzer]=fuzz/gltf.dict [glb_fuzzer]=fuzz/gltf.dict
                       [set_options_fuzzer]=fuzz/set_options.dict)
for target in "${targets[@]}"; do
  # New inputs go to a per-target working corpus (kept between local runs), seeds stay as made.
  corpus="$build/fuzz/corpus/$target"
  mkdir -p "$corpus"
  echo "fuzzing $target for $seconds s"
  log="$build/fuzz/$target.log"
  status=0
  "$build/fuzz/$target" "$corpus" "$seeds/${seed_folder[$target]}" \
    -dict="${dictionary[$target]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=2048 -max_len=3145728 -print_final_stats=1 \
    -artifact_prefix="$build/fuzz/artifacts/$target-" > "$log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    tail -n 150 "$log"
    echo "error: $target failed (exit $status); the input is in $build/fuzz/artifacts/, the log in $log" >&2
    exit 1
  fi
  grep -E "^(INFO: seed corpus|Done|stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ *DONE)" "$log" || tail -n 5 "$log"
done

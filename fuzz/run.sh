#!/usr/bin/env bash
# Builds the libFuzzer harnesses (preset fuzz: clang, -fsanitize=fuzzer,address,undefined) and
# runs each for SECONDS seconds (default 20) from a seed corpus made of the tests' and examples'
# files (and $SFCV_CORPUS when set). Fails on the first crash, leak, timeout or sanitizer report.
# FUZZ_TIMEOUT (seconds, default 10) raises the per-input limit for runs on a loaded machine.
#   fuzz/run.sh [SECONDS] [harness ...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -eq 0 ] && harnesses=(plcopen iec_text g7 agrafe l5x ctl query query_library fbd)

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "${JOBS:-2}" --target $(printf 'fuzz_%s ' "${harnesses[@]}")

work="build/fuzz/runs"
corpus="${SFCV_CORPUS:-}"
seed() {  # seed <harness> <find arguments...>: copies matching files into the seed folder
  local dir="$work/$1/seeds"
  shift
  mkdir -p "$dir"
  local roots=(examples tests share)
  [ -n "$corpus" ] && [ -d "$corpus" ] && roots+=("$corpus")
  find "${roots[@]}" -type f \( "$@" \) -size -200k -exec cp -t "$dir" {} + 2>/dev/null || true
}

for h in "${harnesses[@]}"; do
  case "$h" in
    plcopen) seed "$h" -name '*.xml' ;;
    iec_text) seed "$h" -name '*.st' -o -name '*.sfc' ;;
    g7) seed "$h" -name '*.g7' ;;
    agrafe) seed "$h" -name '*.grafcet' ;;
    l5x) seed "$h" -iname '*.l5x' ;;
    ctl) seed "$h" -name '*.ctl' -o -name '*.spec' ;;
    query) seed "$h" -name '*.sfq' ;;
    query_library) seed "$h" -name '*.sfq' ;;
    fbd) mkdir -p "$work/$h/seeds" ;;  # networks only: fuzz/seeds/fbd
  esac
  # Seeds that exist only as text in fuzz/seeds/<harness>/ (formulas, queries, small charts).
  [ -d "fuzz/seeds/$h" ] && cp fuzz/seeds/"$h"/* "$work/$h/seeds/"
  mkdir -p "$work/$h/corpus" "$work/$h/artifacts"
  echo "== fuzz_$h: ${seconds}s"
  "build/fuzz/fuzz/fuzz_$h" "$work/$h/corpus" "$work/$h/seeds" \
    -dict="fuzz/dict/$h.dict" -max_total_time="$seconds" -timeout="${FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 \
    -max_len=65536 -artifact_prefix="$work/$h/artifacts/" -print_final_stats=1 2>&1 |
    tail -n 25
  status=${PIPESTATUS[0]}
  if [ "$status" -ne 0 ]; then
    echo "fuzz_$h failed (exit $status); inputs in $work/$h/artifacts/" >&2
    exit 1
  fi
done

#!/usr/bin/env bash
# Installs every build and test dependency of sfcv from Debian's packages.
# Idempotent and quiet; fails loudly. Both README commands (make demo, make test) call it.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache  # ccache: .ci/run keeps one cache for its presets
  libpugixml-dev libcli11-dev nlohmann-json3-dev libyaml-cpp-dev
  libbdd-dev libcadical-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  graphviz spin berkeley-abc gnuplot-nox
  python3-jsonschema chromium  # tests: SARIF schema validation, the HTML report in a browser
  libxml2-utils  # tests: xmllint validates the JUnit reports (ctest junit_schema)
  clang libclang-rt-14-dev  # the libFuzzer harnesses of fuzz/ (.ci/run)
  clang-format  # scripts/check-format.sh (ctest clang_format, .ci/run)
  valgrind  # ctest valgrind_grafcet_bdd
  parallel python3-yaml  # ctest distributed_examples: GNU parallel, the CI examples' YAML
  tmux  # ctest progress_tmux: the progress line in an 80-column terminal
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
if ! $SUDO apt-get update -qq >/tmp/sfcv-apt-update.log 2>&1; then
  cat /tmp/sfcv-apt-update.log >&2
  echo "install-deps: apt-get update failed" >&2
  exit 1
fi
if ! $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/tmp/sfcv-apt-install.log 2>&1; then
  cat /tmp/sfcv-apt-install.log >&2
  echo "install-deps: apt-get install failed for: ${missing[*]}" >&2
  exit 1
fi

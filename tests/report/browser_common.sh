# Sourced by the browser tests: their arguments (SFCV SOURCE_DIR OUT_DIR), Debian's chromium
# (exit 77, skipped, without it), the output folder and a temporary folder removed on exit.
sfcv=$1
src=$2
out=$3
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "chromium is not installed (scripts/install-deps.sh installs it): browser test skipped"
  exit 77
fi
mkdir -p "$out"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

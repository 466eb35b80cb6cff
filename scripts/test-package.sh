#!/bin/sh
# Tests the installation (issue 48): `cmake --install` into a temporary prefix, then the Debian
# package of `cpack -G DEB`, unpacked with dpkg-deb; each must hold the binary, its share files,
# the man page, the completions and the documentation, and its binary must run and find the
# query library. With --install (CI, as root): also `dpkg -i` the package into the machine,
# run the installed sfcv, then remove the package.
# Usage: scripts/test-package.sh BUILD_DIR [--install]
set -eu
build=$1
install=${2:-}
if ! command -v cpack >/dev/null || ! command -v dpkg-deb >/dev/null; then
  echo "SKIP: cpack or dpkg-deb missing"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

expect_files() {  # ROOT: the installed tree
  root=$1
  for f in bin/sfcv share/sfcv/properties.sfq share/sfcv/patterns.spec share/man/man1/sfcv.1 \
           share/bash-completion/completions/sfcv share/zsh/vendor-completions/_sfcv \
           share/doc/sfcv/README.md share/doc/sfcv/semantics.md share/doc/sfcv/reports.md \
           share/doc/sfcv/examples/chemical_plant/chemical_plant.st; do
    if [ ! -e "$root/$f" ]; then
      echo "FAIL: $f is not installed under $root"
      exit 1
    fi
  done
  "$root/bin/sfcv" --version | grep -q '^sfcv ' || { echo "FAIL: $root/bin/sfcv --version"; exit 1; }
  # The installed binary finds the query library next to it (share/sfcv), not in the source tree.
  "$root/bin/sfcv" query --list >/dev/null 2>&1 || { echo "FAIL: $root/bin/sfcv query --list"; exit 1; }
  if command -v man >/dev/null; then
    MANWIDTH=80 man -l "$root/share/man/man1/sfcv.1" 2>/dev/null | grep -q "EXIT STATUS" ||
      { echo "FAIL: the man page does not render"; exit 1; }
  fi
  bash -n "$root/share/bash-completion/completions/sfcv" || { echo "FAIL: bash completion syntax"; exit 1; }
}

cmake --install "$build" --prefix "$work/prefix" >/dev/null
expect_files "$work/prefix"
echo "ok: cmake --install"

(cd "$build" && cpack -G DEB -B "$work/deb" >/dev/null)
deb=$(ls "$work"/deb/sfcv_*.deb)
dpkg-deb -x "$deb" "$work/unpacked"
expect_files "$work/unpacked/usr"
dpkg-deb -f "$deb" Depends | grep -q . || { echo "FAIL: the package declares no Depends"; exit 1; }
echo "ok: $(basename "$deb") ($(dpkg-deb -f "$deb" Installed-Size) KB installed)"

if [ "$install" = "--install" ]; then
  dpkg -i "$deb" >/dev/null
  /usr/bin/sfcv --version
  /usr/bin/sfcv check /usr/share/doc/sfcv/examples/chemical_plant/chemical_plant.st \
    --checks reachable --quiet >/dev/null
  man -w sfcv >/dev/null 2>&1 || test -f /usr/share/man/man1/sfcv.1
  dpkg -r sfcv >/dev/null
  echo "ok: dpkg -i, sfcv run from /usr/bin, dpkg -r"
fi

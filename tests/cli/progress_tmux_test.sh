#!/bin/sh
# The progress line in a real terminal of 80 columns (tmux), as an engineer sees it during a long
# `sfcv check --engine auto` (issue 48): it refreshes in place and is never wider than the
# terminal, so the screen never scrolls (before: padded to 99 columns, each refresh wrapped onto
# a new line, 19 lines in 12 s), and it shows each engine of the race.
# Usage: progress_tmux_test.sh SFCV
set -eu
sfcv=$1
command -v tmux >/dev/null 2>&1 || { echo "tmux is not installed (scripts/install-deps.sh)"; exit 77; }
dir=$(mktemp -d)
sock="sfcv-progress-$$"
trap 'tmux -L "$sock" kill-server 2>/dev/null || true; rm -rf "$dir"' EXIT
# 24 independent partial grafcets, one input each: 2^24 situations, more than auto's explicit
# phase takes, so the bdd, ic3 and bmc engines race until the time limit.
{
  echo "project wide;"
  i=1
  while [ $i -le 24 ]; do echo "input a$i;"; i=$((i + 1)); done
  i=1
  while [ $i -le 24 ]; do
    echo "grafcet g$i { step ${i}0 initial; step ${i}1;"
    echo "  transition t$i: ${i}0 -> ${i}1 when a$i; transition u$i: ${i}1 -> ${i}0 when !a$i; }"
    i=$((i + 1))
  done
} >"$dir/wide.g7"
tmux -L "$sock" -f /dev/null new-session -d -x 80 -y 24 \
  "'$sfcv' check '$dir/wide.g7' --timeout 8 >'$dir/out.txt'; echo \$? >'$dir/rc'; sleep 120"
k=0
while [ ! -f "$dir/rc" ] && [ $k -lt 120 ]; do
  sleep 0.5
  k=$((k + 1))
  tmux -L "$sock" capture-pane -p -S -200 >"$dir/screen$k.txt"
done
[ -f "$dir/rc" ] || { echo "sfcv did not end within 60 s of a --timeout 8"; exit 1; }
rc=$(cat "$dir/rc")
[ "$rc" -eq 3 ] || { echo "exit $rc, expected 3 (unknown at the time limit)"; cat "$dir/out.txt"; exit 1; }
shown=0
for f in "$dir"/screen*.txt; do
  lines=$(grep -c '^sfcv: \(race\|explore\|build\|load\|check\)' "$f" || true)
  if [ "$lines" -gt 1 ]; then
    echo "$(basename "$f"): $lines progress lines on the screen: the line scrolled"
    cat "$f"
    exit 1
  fi
  [ "$lines" -eq 1 ] && shown=$((shown + 1))
  wide=$(grep '^sfcv: \(race\|explore\|build\|load\|check\)' "$f" | awk 'length($0) > 79' || true)
  [ -z "$wide" ] || { echo "a progress line wider than 79 columns: $wide"; exit 1; }
done
[ "$shown" -ge 3 ] || { echo "the progress line was seen on $shown screens (expected at least 3)"; exit 1; }
for racer in bdd ic3 bmc; do
  cat "$dir"/screen*.txt | grep '^sfcv: race:' | grep -q "| $racer " ||
    { echo "no screen shows the $racer engine's part of the race"; exit 1; }
done
echo "progress line: $shown screens, never scrolled, at most 79 columns, every racer shown"

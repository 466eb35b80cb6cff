#!/bin/sh
# N shards on one machine with GNU parallel, then the merge (docs/distributed.md):
#   examples/distributed/parallel.sh 4 plant.st --checks all
# SFCV (default: sfcv) and OUT (default: a fresh temporary directory) may be set. Prints the
# merged report; exits as sfcv check would have.
set -eu
n=$1
shift
sfcv=${SFCV:-sfcv}
out=${OUT:-$(mktemp -d)}
# Each shard in its own process; the exit codes 1 and 3 are answers the merge gives again.
seq 1 "$n" | parallel --will-cite --halt never \
  "'$sfcv' check $(printf "'%s' " "$@") --json --quiet --shard {}/$n > '$out'/shard-{}.json" || true
shards=$(seq 1 "$n" | sed "s|.*|$out/shard-&.json|")
# shellcheck disable=SC2086 # one word per shard file
exec "$sfcv" merge $shards

#!/bin/sh
# A Slurm job array, one task per shard (docs/distributed.md):
#   sbatch --array=1-4 examples/distributed/slurm-array.sh plant.st --checks all
# then, when every task is done:
#   sfcv merge shard-*.json
# SLURM_ARRAY_TASK_ID is this task's shard, SLURM_ARRAY_TASK_COUNT the number of shards.
# SFCV (default: sfcv) and OUT (default: the working directory) may be set.
#SBATCH --job-name=sfcv-shard
#SBATCH --cpus-per-task=1
set -eu
: "${SLURM_ARRAY_TASK_ID:?run me as a job array task (sbatch --array=1-N)}"
count=${SLURM_ARRAY_TASK_COUNT:-${SLURM_ARRAY_TASK_MAX:?no SLURM_ARRAY_TASK_COUNT}}
out=${OUT:-.}/shard-$SLURM_ARRAY_TASK_ID.json
status=0
"${SFCV:-sfcv}" check "$@" --json --quiet --shard "$SLURM_ARRAY_TASK_ID/$count" > "$out" || status=$?
# 1 (violated) and 3 (unknown) are answers for the merge; 2 and 4 are errors of this task.
[ "$status" -eq 0 ] || [ "$status" -eq 1 ] || [ "$status" -eq 3 ]

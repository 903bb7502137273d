#!/usr/bin/env bash
# A kinrepro optimisation in shards (of its searches: combinations of listed
# values x --starts), one Slurm array task per shard:
#
#   sbatch --array=1-N examples/slurm/optimize-array.sh SCENE OUTDIR --vary FIELD=RANGE --objective OUTPUT:min|max [OPTIMIZE FLAGS...]
#   kinrepro merge OUTDIR/part-*.json --format json > optimum.json
#
# Task I of N runs `kinrepro optimize SCENE --shard I/N --json [FLAGS]`
# into OUTDIR/part-I.json (written whole: to a temporary name, then
# renamed). The shards take the searches by index, so the
# merge is exactly the optimisation run in one piece; `merge` names a missing
# shard; resubmit it alone with the shard count given, e.g. for shard 3 of
# 4: `sbatch --array=3 --export=ALL,KINREPRO_SHARDS=4 ...` (an array of one
# task counts one). kinrepro comes from $KINREPRO when set, else from PATH. Give each
# task the cores it uses with --cpus-per-task and the same number to
# `--jobs` among the flags.
#SBATCH --job-name=kinrepro-optimize
#SBATCH --output=kinrepro-optimize-%A_%a.out
set -euo pipefail
if [ "$#" -lt 2 ]; then
    echo "usage: sbatch --array=1-N $0 SCENE OUTDIR --vary FIELD=RANGE --objective OUTPUT:min|max [OPTIMIZE FLAGS...]" >&2
    exit 2
fi
scene="$1"
out="$2"
shift 2
: "${SLURM_ARRAY_TASK_ID:?run it as an array job: sbatch --array=1-N}"
: "${SLURM_ARRAY_TASK_COUNT:?run it as an array job: sbatch --array=1-N}"
kinrepro="${KINREPRO:-kinrepro}"
mkdir -p "$out"
shards="${KINREPRO_SHARDS:-$SLURM_ARRAY_TASK_COUNT}"
part="$out/part-$SLURM_ARRAY_TASK_ID.json"
"$kinrepro" optimize "$scene" --shard "$SLURM_ARRAY_TASK_ID/$shards" \
    --json "$@" > "$part.tmp"
mv "$part.tmp" "$part"

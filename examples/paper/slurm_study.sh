#!/bin/bash
# One study of the paper on a Slurm cluster: one allocation, LIGGGHTS's multi-partition mode
# (run_study.py --mode partitions: batches of one run per partition, `mpirun -np P*K
# liggghts-lbm -partition PxK -in in.study`; a failing run takes its batch down and the rest
# of the batch is relaunched, see ensemble.py). Edit the #SBATCH lines to the study's size:
# run_study.py <study> --size paper --dry-run prints its runs and core-hours.
#
#   sbatch --export=STUDY=dropvol,SIZE=paper examples/paper/slurm_study.sh
#
# P = SLURM_NTASKS / RANKS_PER_RUN runs at a time. With 100 runs on 100 tasks, one batch.
# At the paper size the runner keeps each finished run in doc/paper/<study>/ and, when Slurm
# ends the job (SIGTERM), parks the runs cut short there: commit it, and the next job (here or
# on any clone) continues the study from it (committed_runs.py).
#SBATCH --job-name=lbm-pore-study
#SBATCH --ntasks=100
#SBATCH --cpus-per-task=1
#SBATCH --time=12:00:00
#SBATCH --output=study_%j.out
set -euo pipefail
STUDY=${STUDY:-dropvol}
SIZE=${SIZE:-paper}
RANKS_PER_RUN=${RANKS_PER_RUN:-1}
REPO=${REPO:-$(cd "$(dirname "$0")/../.." && pwd)}
OUT=${OUT:-$PWD/${STUDY}_${SIZE}}
export OMP_NUM_THREADS=1
# mpirun inside the allocation starts the ranks on its nodes (Open MPI reads Slurm's
# environment)
python3 "$REPO/examples/paper/run_study.py" "$STUDY" --size "$SIZE" --out "$OUT" \
    --mode partitions --parallel $((SLURM_NTASKS / RANKS_PER_RUN)) \
    --ranks-per-run "$RANKS_PER_RUN" --driver "$REPO/build/liggghts_plugin/liggghts-lbm" \
    --mpirun mpirun

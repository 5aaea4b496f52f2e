#!/usr/bin/env bash
# Runs the TCAF example (examples/tcaf/in.tcaf) in chunks of one block (5,130 steps) each, every chunk continuing from
# tcaf.restart, then fits the correlations with python/tcaf_fit.py into results/.
#   bash validation/tcaf/run.sh [LAST [FIRST]]     # chunks FIRST..LAST (default 0..11: 12 blocks)
# A stopped run is continued with FIRST = the next chunk. Set ETD_DPD_RANKS=N for MPI.
# One block takes about 2 min 20 s on one core (13,500 atoms).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/../.." && pwd)
. "$top/tools/lammps_env.sh"
last=${1:-11}; first=${2:-0}
ranks=${ETD_DPD_RANKS:-1}
mpi=(mpirun -np "$ranks"); [ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root --oversubscribe)
cd "$here"
for ((c = first; c <= last; c++)); do
  "${mpi[@]}" "$LMP" -in "$top/examples/tcaf/in.tcaf" -var plugin "$PLUGIN" -var chunk "$c" \
    -log "log.chunk.$c" -screen none
  echo "chunk $c done: tcaf.$c.dat"
done
/usr/bin/python3 "$top/python/tcaf_fit.py" tcaf.*.dat --box 15 --rho 4 --natoms 13500 \
  --reference "kinetic theory=30" --out results/tcaf_fit 2>&1 | grep -v skipping

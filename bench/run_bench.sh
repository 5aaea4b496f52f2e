#!/usr/bin/env bash
# Throughput of ETD-DPD against stock LAMMPS DPD, side by side in one LAMMPS run per rank count.
# Usage: bash bench/run_bench.sh [steps]      (writes bench/results/: the logs and the table throughput.md)
#        BENCH_RANKS="1" bash bench/run_bench.sh 300     (only these rank counts)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
. "$here/tools/lammps_env.sh"
steps=${1:-500}
out="$here/bench/results"
mkdir -p "$out"
mpi_flags=()
[ "$(id -u)" = 0 ] && mpi_flags+=(--allow-run-as-root)
for ranks in ${BENCH_RANKS:-1 2}; do
  mpirun "${mpi_flags[@]}" -np $ranks "$LMP" -in "$here/bench/in.pair_throughput" \
    -var plugin "$PLUGIN" -var steps "$steps" -log "$out/log.np$ranks" -screen none
done
logs=(); for ranks in ${BENCH_RANKS:-1 2}; do logs+=("$out/log.np$ranks"); done
/usr/bin/python3 "$here/bench/throughput_table.py" "${logs[@]}" | tee "$out/throughput.md"    # the summary; the logs are not kept

#!/usr/bin/env bash
# Set everything up and run the package's main job: examples/quickstart, a low-mass DPD fluid
# (m = 0.01, s = 1/2) integrated with fix etd at a step velocity-Verlet cannot take.
# Outputs go to out/quickstart/ (log.lammps, thermo data). Set ETD_DPD_RANKS to run with MPI.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
prefix=$(bash "$here/tools/bootstrap.sh" | sed -n 's/^LAMMPS_PREFIX=//p')
ranks=${ETD_DPD_RANKS:-1}
out="$here/out/quickstart"
mkdir -p "$out"
cd "$out"
mpi_flags=(--oversubscribe)
[ "$(id -u)" = 0 ] && mpi_flags+=(--allow-run-as-root)
start=$(date +%s.%N)
mpirun "${mpi_flags[@]}" -np "$ranks" "$prefix/bin/lmp" -in "$here/examples/quickstart/in.quickstart" \
  -var plugin "$here/build/etddpdplugin.so" -log "$out/log.lammps" -screen none
end=$(date +%s.%N)
/usr/bin/python3 "$here/python/summarise_log.py" "$out/log.lammps" --target-temperature 1.0 \
  --wall "$(python3 -c "print($end - $start)")" --outputs "$out"

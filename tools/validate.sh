#!/usr/bin/env bash
# Long physics validation (not part of CI): equilibrium kBT against time step for fix etd
# (order 1 with both noise variants, and order 2) and the stock dpd/ext + fix nve at m = 0.01, side by side with
# Mai-Duy et al.'s (2013) Table 3. Takes about 10 minutes on 2 cores; writes doc/validation_temperature.md.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
prefix=$(bash "$here/tools/bootstrap.sh" 2>/dev/null | sed -n 's/^LAMMPS_PREFIX=//p')
out="$here/out/validation"; mkdir -p "$out"; cd "$out"
results="$out/results.txt"; : >"$results"
run() {    # pair integrator dt
  "$prefix/bin/lmp" -in "$here/validation/in.temperature_scan" -var plugin "$here/build/etddpd.so" \
    -var pair "$1" -var integrator "$2" -var dt "$3" -var mass 0.01 -log none -screen screen.txt >/dev/null 2>&1 \
    && grep -h RESULT screen.txt | tail -1 >>"$results" \
    || echo "RESULT pair=$1 integrator=$2 mass=0.01 dt=$3 kBT=fails" >>"$results"
}
for dt in 0.0005 0.001 0.003; do
  run gen etd "$dt"
  run gen "etd noise exact" "$dt"
  run gen "etd order 2" "$dt"
done
for dt in 0.0005 0.001; do run stock nve "$dt"; done
{
  echo "# Equilibrium kBT at m = 0.01 (4,000 atoms, periodic, 4 time units after 1 of equilibration)"
  echo
  echo "Seed 000, Table 3 (with walls): ETD 0.9958 (dt 0.0005), 0.9835 (0.001), 0.9356 (0.003);"
  echo "velocity-Verlet 0.9322 (0.0005), fails at dt >= 0.0009."
  echo
  echo '| pair | integrator | dt | kBT |'
  echo '|---|---|---|---|'
  sed -E 's/RESULT pair=(\S+) integrator=(.*) mass=\S+ dt=(\S+) kBT=(\S+)/| \1 | \2 | \3 | \4 |/' "$results"
} >"$here/doc/validation_temperature.md"
cat "$here/doc/validation_temperature.md"

#!/usr/bin/env bash
# Long physics validation of fix etd scheme implicit (not part of CI): temperature and
# reverse-Poiseuille viscosity against time step at m = 0.01 and 0.001, with velocity-Verlet
# (dpd/gen + fix nve) at a small step as the reference, and m = 0.0001 towards the zero-mass
# limit. Takes about 10 minutes on 2 cores; writes
# validation/implicit/README.md. Usage: bash validation/implicit/run.sh [production time units]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
time_units=${1:-4}
out="$here/out/validation_implicit"; mkdir -p "$out"; cd "$out"
table="$out/table.md"
echo "| m | integrator | dt | kBT | eta (reverse Poiseuille, g = 0.3) | D (MSD in y, z) |" >"$table"
echo "|---|---|---|---|---|---|" >>"$table"
run() {    # mass integrator dt time
  local name="p_${1}_${2// /_}_${3}.txt"
  if "$LMP" -in "$here/validation/implicit/in.reverse_poiseuille" -var plugin "$PLUGIN" \
      -var mass "$1" -var integrator "$2" -var dt "$3" -var time "$4" -var out "$name" \
      -log none -screen screen.txt >/dev/null 2>&1; then
    local kT eta diffusivity
    kT=$(sed -n 's/.*kBT=\([0-9.]*\).*/\1/p' screen.txt | tail -1)
    diffusivity=$(sed -n 's/.* D=\([0-9.]*\).*/\1/p' screen.txt | tail -1)
    eta=$(/usr/bin/python3 "$here/python/viscosity_fit.py" "$name" --force 0.3 | sed 's/ *(.*//; s/eta = //')
    echo "| $1 | $2 | $3 | $kT | $eta | $diffusivity |" >>"$table"
  else
    echo "| $1 | $2 | $3 | fails | |" >>"$table"
  fi
  tail -1 "$table"
}
run 0.01 nve 0.0005 "$time_units"
run 0.01 "etd" 0.0005 "$time_units"
for dt in 0.001 0.003 0.01; do run 0.01 "etd scheme implicit" "$dt" "$time_units"; done
run 0.001 nve 0.00005 "$(awk "BEGIN { print $time_units / 2 }")"
for dt in 0.0003 0.001 0.003; do run 0.001 "etd scheme implicit" "$dt" "$time_units"; done
# towards the zero-mass limit: the inertial scheme at m = 0.0001
run 0.0001 "etd scheme implicit" 0.001 "$time_units"
{
  echo "# fix etd scheme implicit: temperature and viscosity against time step"
  echo
  echo "4,000 atoms, periodic 10^3 box, n = 4, a = 18.75, gamma = 4.5, sigma = 3, s = 1/2, kBT = 1;"
  echo "body force +-0.3 along x in the two halves, viscosity from the parabolic fit"
  echo "(python/viscosity_fit.py, error from the bins' scatter). Command: bash validation/implicit/run.sh $time_units"
  echo "(production $time_units time units after 1 of equilibration; half of that for velocity-Verlet at m = 0.001)."
  echo
  cat "$table"
} >"$here/validation/implicit/README.md"
cat "$here/validation/implicit/README.md"

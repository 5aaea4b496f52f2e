#!/usr/bin/env bash
# Long physics validation (not part of CI): the zero-mass limit of fix etd scheme implicit.
# Reverse Poiseuille flow (validation/implicit/in.reverse_poiseuille: 4,000 atoms, n = 4, a = 18.75,
# gamma = 4.5, s = 1/2, kBT = 1, g = 0.3): viscosity, self-diffusion across the flow, CG
# iterations and cost per time unit for the inertial scheme at m = 0.01, 0.001, 0.0001 and for
# overdamped yes, midpoint (default) and single solve (midpoint no), at several steps. The
# overdamped runs start from a configuration equilibrated with the inertial scheme (m = 0.01,
# dt = 0.003). Writes out/validation_overdamped/table.md.
# Usage: bash validation/overdamped/run.sh [production time units, default 10] (about 25 min)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
time_units=${1:-10}
out="$here/out/validation_overdamped"; mkdir -p "$out"; cd "$out"
table="$out/table.md"
echo "| m | scheme | dt | kBT | eta | D (y, z) | CG iterations per solve | steps keeping the predictor | s per time unit |" >"$table"
echo "|---|---|---|---|---|---|---|---|---|" >>"$table"
run() {    # label mass integrator dt [extra lmp args]
  local label=$1 mass=$2 integrator=$3 dt=$4; shift 4
  local name="p_${mass}_${dt}_${label// /_}"
  if "$LMP" -in "$here/validation/implicit/in.reverse_poiseuille" -var plugin "$PLUGIN" \
      -var mass "$mass" -var integrator "$integrator" -var dt "$dt" -var time "$time_units" \
      -var out "$name.txt" -var iterations yes "$@" -log "$name.log" -screen none >/dev/null 2>&1; then
    local kT D eta iters kept seconds steps
    kT=$(sed -n 's/.*kBT=\([0-9.]*\).*/\1/p' "$name.log" | tail -1)
    D=$(sed -n 's/.* D=\([0-9.]*\).*/\1/p' "$name.log" | tail -1)
    iters=$(sed -n 's/.*ITERATIONS=\([0-9.]*\).*/\1/p' "$name.log" | tail -1)
    kept=$(sed -n 's/.*PREDICTOR_ONLY=\([0-9]*\).*/\1/p' "$name.log" | tail -1)
    eta=$(/usr/bin/python3 "$here/python/viscosity_fit.py" "$name.txt" --force 0.3 | sed 's/ *(.*//; s/eta = //')
    read -r seconds steps < <(sed -n 's/^Loop time of \([0-9.]*\) on [0-9]* procs for \([0-9]*\) steps.*/\1 \2/p' "$name.log" | tail -1)
    local cost; cost=$(awk "BEGIN { printf \"%.1f\", $seconds / ($steps * $dt) }")
    case $label in overdamped*) kT="(not a temperature)" ;; *) kept="" ;; esac
    echo "| $mass | $label | $dt | $kT | $eta | $D | $iters | $kept | $cost |" >>"$table"
  else
    echo "| $mass | $label | $dt | fails | | | | | |" >>"$table"
  fi
  tail -1 "$table"
}
run inertial 0.01 "etd scheme implicit" 0.003
run inertial 0.001 "etd scheme implicit" 0.001
run inertial 0.0001 "etd scheme implicit" 0.0003
for dt in 0.001 0.003 0.01; do
  run "overdamped midpoint" 0.01 "etd scheme implicit overdamped yes" "$dt" -var equil_inertial yes -var equil_dt 0.003
done
for dt in 0.001 0.003 0.01; do
  run "overdamped single solve" 0.01 "etd scheme implicit overdamped yes midpoint no" "$dt" \
    -var equil_inertial yes -var equil_dt 0.003
done
cat "$table"

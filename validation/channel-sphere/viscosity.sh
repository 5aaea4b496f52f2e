#!/bin/bash
# The channel-sphere fluid's shear viscosity measured (README section 6): reverse Poiseuille
# runs of in.fluid_viscosity at two forces and three seeds with the paper's step, and two seeds
# at half the step; profiles, logs and the fits go to results/viscosity/.
# Run from anywhere: bash validation/channel-sphere/viscosity.sh  (about 20 minutes on one core)
set -e
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/../../tools/lammps_env.sh"
out=$here/results/viscosity
mkdir -p "$out"
cd "$out"
run() {  # g dt steps seed
  local name=viscosity.g$1.dt$2.s$4
  "$LMP" -in "$here/in.fluid_viscosity" -var plugin "$PLUGIN" -var g "$1" -var dt "$2" \
    -var equil "$(( $3 / 8 ))" -var steps "$3" -var seed "$4" -var out "$name" -log "log.$name" -screen none
  grep '^RESULT' "log.$name"
}
for seed in 1 2 3; do
  run 0.02 0.01 40000 $seed
  run 0.04 0.01 40000 $seed
done
for seed in 1 2; do run 0.02 0.005 80000 $seed; done
# fits: one line per run (the box height is the lattice's, printed by each run)
for log in log.viscosity.*; do
  name=${log#log.}
  g=$(sed -n 's/^RESULT.* g=\([^ ]*\).*/\1/p' "$log")
  Lz=$(sed -n 's/^RESULT.* Lz=\([^ ]*\).*/\1/p' "$log")
  echo "$name $(grep '^RESULT' "$log" | sed 's/.*atoms=[^ ]* //') $(/usr/bin/python3 "$here/../../python/viscosity_fit.py" "$name" --force "$g" --box "$Lz" --density 4)"
done | tee fits.txt

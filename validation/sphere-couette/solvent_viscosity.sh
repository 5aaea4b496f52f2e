#!/usr/bin/env bash
# The shear viscosity of the sphere-couette solvent (n = 4, a = 18.75, sigma = 2 so gamma = 8,
# s = 1/2, kBT = 0.25, m = 0.01) against the shear rate, by homogeneous shear with Lees-Edwards
# boundaries (examples/shear/in.shear with kT 0.25 gamma 8.0): the paper normalises its drag with
# eta = 3.9682. Writes results/solvent_viscosity/log.<integ>.<rate>.<seed> (not kept in the
# repository), prints the RESULT lines and collects them, one line per run, in the summary
# results/solvent_viscosity.txt. About 20 minutes of one core.
# Usage: bash validation/sphere-couette/solvent_viscosity.sh
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/tools/lammps_env.sh"
out="$here/results/solvent_viscosity"
mkdir -p "$out"
cd "$out"
run() {    # integ dt rate seed tstart tprod
  "$LMP" -in "$root/examples/shear/in.shear" -var plugin "$PLUGIN" -var integ "$1" -var dt "$2" \
    -var rate "$3" -var seed "$4" -var tstart "$5" -var tprod "$6" -var kT 0.25 -var gamma 8.0 \
    -log "log.$1.$3.$4" -screen none
  grep '^RESULT' "log.$1.$3.$4"
}
for seed in 11 12 13; do run diag 0.001 0.2 $seed 1.5 6; run diag 0.001 0.5 $seed 1.5 6; done
for seed in 11 12; do run diag 0.001 2 $seed 1.5 4; run diag 0.001 4 $seed 1.5 4; done
run implicit 0.001 0.2 11 1.5 4
run implicit 0.001 0.2 12 1.5 6
for seed in 11 12; do run implicit 0.001 0.5 $seed 1.5 4; done
run stock 0.0002 0.2 11 1.0 3
run stock 0.0002 0.5 11 1.0 2
grep -H '^RESULT' log.* | sed 's/^log\.//; s/:RESULT / /' > "$here/results/solvent_viscosity.txt"    # the summary

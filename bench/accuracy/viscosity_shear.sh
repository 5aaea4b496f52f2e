#!/usr/bin/env bash
# The viscosity column of the accuracy matrix on the Groot-Warren fluid (n = 3, a = 25,
# gamma = 4.5, s = 2, kBT = 1) at m = 0.01 by homogeneous shear (examples/shear/in.shear:
# Lees-Edwards boundaries through fix deform ... remap v, eta = -<P_xy> / rate at rate 2,
# 0.5 time units of start-up and 4 of averaging, 3,000 atoms): stock pair dpd + nve at the
# reference step 0.0001 and at its largest step 0.0007, fix etd scheme implicit at its largest
# steps (0.007 default, 0.005 with tol 1e-4 start velocity), four seeds each. Reverse Poiseuille
# flow (viscosity.sh) does not resolve 2 % on this fluid in 20 time units; this does.
# Writes results/viscosity_shear/log.<cell>.<seed> and prints the RESULT lines. About 12 minutes.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$root/tools/lammps_env.sh"
out="$here/results/viscosity_shear"
mkdir -p "$out"
cd "$out"
fluid=(-var n 3 -var a 25 -var s 2 -var gamma 4.5 -var kT 1.0 -var mass 0.01 -var rate 2
       -var tstart 0.5 -var tprod 4)
run() {    # cell integ dt fixopts seed
  "$LMP" -in "$root/examples/shear/in.shear" -var plugin "$PLUGIN" "${fluid[@]}" -var integ "$2" \
    -var dt "$3" -var fixopts "$4" -var seed "$5" -log "log.$1.$5" -screen none
  echo "$1 $(grep '^RESULT' "log.$1.$5")"
}
for seed in 1 2 3 4; do
  run ref stock 0.0001 "" $seed
  run stock stock 0.0007 "" $seed
  run imp implicit 0.007 "" $seed
  run impv implicit 0.005 "tol 1e-4 start velocity" $seed
done

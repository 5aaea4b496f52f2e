#!/usr/bin/env bash
# Zero-shear reference for the shear runs: TCAF viscosity of the same fluid at equilibrium
# (examples/shear/in.tcaf), then the fit with python/tcaf_fit.py into results/tcaf/INTEG-DT_* (run.sh draws the eta_0 of
# results/tcaf/nve-0.0005_summary.txt, the default, as the zero-shear line of the plot).
#   bash validation/shear/run_tcaf.sh [TIME [INTEG [DT]]]    # default 30 nve 0.0005 (about 5 min)
# Environment: LMP, PLUGIN as in run.sh.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/../.." && pwd)
. "$top/tools/lammps_env.sh"
plugin=$PLUGIN
time=${1:-30} integ=${2:-nve} dt=${3:-0.0005}
cd "$here"
mkdir -p results/tcaf logs
"$LMP" -in "$top/examples/shear/in.tcaf" -var plugin "$plugin" -var integ "$integ" -var dt "$dt" -var time "$time" \
  -var file "tcaf.$integ-$dt.dat" -log "logs/log.tcaf.$integ-$dt" -screen none
grep '^Loop time' "logs/log.tcaf.$integ-$dt" | tail -1
/usr/bin/python3 "$top/python/tcaf_fit.py" "tcaf.$integ-$dt.dat" --box 10 --rho 0.04 --dt "$dt" \
  --natoms 4000 --out "results/tcaf/$integ-$dt" 2>&1 | grep -v skipping

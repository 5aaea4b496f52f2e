#!/usr/bin/env bash
# The sphere spun at fixed Omega with the torque split into its parts (README section 5):
# Omega = -6 in the paper's 10^3 box and in an 8^3 box (the periodic images), 200,000 steps
# each after 2,000 (about 15 CPU-minutes in all). Output: results/rotating_sphere/.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
out="$here/validation/fpm/results/rotating_sphere"; mkdir -p "$out"; cd "$out"
for L in 10 8; do
  "$LMP" -in "$here/validation/fpm/in.fpm_rotating_sphere" -var plugin "$PLUGIN" \
    -var potentials "$here/potentials" -var out "spin_L$L" -var L "$L" -var Omega -6.0 \
    -var equil 2000 -var steps 200000 -log "log.spin_L$L" -screen none
  grep -h RESULT "log.spin_L$L"
done
/usr/bin/python3 "$here/python/fpm_analysis.py" "$out" --torque "L = 10" spin_L10.torque -6.0 \
  --torque "L = 8" spin_L8.torque -6.0 | tee results.md

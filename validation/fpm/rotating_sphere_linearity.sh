#!/usr/bin/env bash
# Is the spun sphere's rotational friction the same at the free sphere's spin rate? (README
# section 5.1): Omega = -1 (400,000 steps) and -3 (200,000) in the 8^3 box, torque split, beside
# the Omega = -6 runs of rotating_sphere_split.sh; two runs at a time (about 16 CPU-minutes).
# Output: results/rotating_sphere/spin_L8_W*.torque, logs, linearity.md.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
out="$here/validation/fpm/results/rotating_sphere"; mkdir -p "$out"; cd "$out"
run() {    # Omega steps
  "$LMP" -in "$here/validation/fpm/in.fpm_rotating_sphere" -var plugin "$PLUGIN" \
    -var potentials "$here/potentials" -var out "spin_L8_W$1" -var L 8 -var Omega "-$1" \
    -var equil 2000 -var steps "$2" -log "log.spin_L8_W$1" -screen none
}
run 1 400000 & run 3 200000 & wait
/usr/bin/python3 "$here/python/fpm_analysis.py" "$out" --torque "L = 8" spin_L8_W1.torque -1.0 \
  --torque "L = 8" spin_L8_W3.torque -3.0 --torque "L = 8" spin_L8.torque -6.0 \
  | tee linearity.md

#!/usr/bin/env bash
# The rotational friction measured inside the Couette box (README section 5.1). The Couette
# case of section 2 (wall speed 8, (1/2) curl v = 0.99), the odd colloids held at Omega = 0 and
# the even ones spun at a fixed Omega about y instead of spinning freely, torques split
# (compute dpd/split torque yes), so that T_fixed - T_spun = B Omega:
#   spun_s7713, spun_s7801   Omega = 0.9895 (the half vorticity): 2,000 time units each
#   fast_U8                  Omega = 6 in the same shear flow: 1,000 time units
#   fast_U0                  Omega = 6 with the walls at rest (no shear): 1,000 time units
# Two runs at a time (about 40 CPU-minutes in all). Usage: couette_spun.sh [all | fast | analyse]
# Output: results/couette_spun/.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
out="$here/validation/fpm/results/couette_spun"; mkdir -p "$out"; cd "$out"
what=${1:-all}
run() {    # name U Omega seed steps
  "$LMP" -in "$here/validation/fpm/in.fpm_wall_channel" -var plugin "$PLUGIN" \
    -var potentials "$here/potentials" -var flow couette -var U "$2" -var steps "$5" \
    -var even_mode spun -var even_spin "$3" -var seed "$4" -var out "$1" \
    -log "log.$1" -screen none
  rm -f "$1.far"
}
if [ "$what" = all ]; then
  run spun_s7713 8.0 0.9895 7713 200000 & run spun_s7801 8.0 0.9895 7801 200000 & wait
fi
if [ "$what" = all ] || [ "$what" = fast ]; then
  run fast_U8 8.0 6.0 7901 100000 & run fast_U0 0.0 6.0 7902 100000 & wait
fi
/usr/bin/python3 "$here/python/fpm_analysis.py" . --couette "spun, seed 7713" spun_s7713 8 \
  --couette "spun, seed 7801" spun_s7801 8 --couette "Omega = 6, wall speed 8" fast_U8 8 \
  --couette "Omega = 6, walls at rest" fast_U0 8 | tee results.md

#!/usr/bin/env bash
# The fluid between two fixed dpd/fpm colloids (README section 4.1): density and v_x along the
# line through their centres for l = 1, 1.5, 2 in the cube of side 8 at u = 0.6, 100,000 steps
# each after 15,000 (about 6 CPU-minutes in all). Output: results/two_spheres/profile_l*.profile.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
out="$here/validation/fpm/results/two_spheres"; mkdir -p "$out"; cd "$out"
for spec in "1.0 0.01442" "1.5 0.01554" "2.0 0.01615"; do
  set -- $spec
  "$LMP" -in "$here/validation/fpm/in.fpm_periodic_drag" -var plugin "$PLUGIN" \
    -var potentials "$here/potentials" -var out "profile_l$1" -var L 8 -var l "$1" -var g "$2" \
    -var u0 0.6 -var equil 15000 -var steps 100000 -var seed 3301 -var profile yes \
    -log "log.profile_l$1" -screen none
done
rm -f profile_l*.drag    # the drag and torque of these short runs are not used

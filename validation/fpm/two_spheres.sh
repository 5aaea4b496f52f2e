#!/usr/bin/env bash
# Two fixed dpd/fpm colloids side by side across a uniform flow (Pan, Pivkin and Karniadakis
# 2008, Table 3; README section 4.1): separations l = 1, 1.5, 2 in a periodic cube of side 8,
# and l = 1 in cubes of side 10 and 12, all at a superficial velocity of about 0.6, each with the
# torque split into its dissipative and random parts (compute dpd/split torque yes). A second
# seed repeats l = 1, L = 8. Block files, logs and the table go to results/two_spheres/.
#
#   bash validation/fpm/two_spheres.sh        (about 100 CPU-minutes on one core)
# g gives u = 0.6 for each l and L: F = 6 pi mu R f(l) u / (1 - 2 x 2.837 R f(l) / L) per sphere,
# g = 2 F / N_fluid (python/etddpd/fpm_analysis.py two_spheres has the same formula).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
out="$here/validation/fpm/results/two_spheres"; mkdir -p "$out"; cd "$out"
cp "$PLUGIN" "$out/etddpdplugin.so"    # a private copy: rebuilds do not touch running jobs
run() {    # name L l g equil steps seed
  echo "running $1"
  "$LMP" -in "$here/validation/fpm/in.fpm_periodic_drag" -var plugin "$out/etddpdplugin.so" \
    -var potentials "$here/potentials" -var out "$1" -var L "$2" -var l "$3" -var g "$4" \
    -var u0 0.6 -var equil "$5" -var steps "$6" -var seed "$7" -log "log.$1" -screen none
  grep -h RESULT "log.$1" | tail -1
}
run pair_L8_l1 8 1.0 0.01442 15000 400000 5281
run pair_L8_l1.5 8 1.5 0.01554 15000 800000 5281
run pair_L8_l2 8 2.0 0.01615 15000 1200000 5281
run pair_L10_l1 10 1.0 0.0071 20000 400000 5281
run pair_L12_l1 12 1.0 0.00401 30000 400000 5281
run pair_L8_l1_s2 8 1.0 0.01442 15000 400000 7717
rm -f "$out/etddpdplugin.so"
/usr/bin/python3 "$here/python/fpm_analysis.py" "$out" \
  --pair "L = 8" pair_L8_l1.drag 8 0.01442 1534 1.0 \
  --pair "L = 8, second seed" pair_L8_l1_s2.drag 8 0.01442 1534 1.0 \
  --pair "L = 8" pair_L8_l1.5.drag 8 0.01554 1534 1.5 \
  --pair "L = 8" pair_L8_l2.drag 8 0.01615 1534 2.0 \
  --pair "L = 10" pair_L10_l1.drag 10 0.0071 2998 1.0 \
  --pair "L = 12" pair_L12_l1.drag 12 0.00401 5182 1.0 | tee results.md

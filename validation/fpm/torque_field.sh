#!/usr/bin/env bash
# The two-sphere torque from the fluid's fields (README section 4.2): the fluid's density,
# velocity and spin in 3-D bins of 0.1 about colloid 1, for one colloid alone (l = 0) and for
# the pair at l = 1, 1.5 and 2, in the cube of side 8 at u = 0.6, two runs at a time (about
# 15 CPU-minutes); then eight more seeds at l = 1.5, where the torque is smallest against its
# noise (about 30 CPU-minutes); then one colloid with its flow in rings about the stream's axis
# (about 8 CPU-minutes). python/fpm_torque_field.py compares the torque summed from the
# fields with the measured one and with the same pair law applied to Stokes flow.
# Usage: torque_field.sh [all | first | repeats | axial | analyse]   (default all)
# Output: results/torque_field/field_l*.{field,drag}, logs, summary.txt.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
out="$here/validation/fpm/results/torque_field"; mkdir -p "$out"; cd "$out"
what=${1:-all}
run() {    # l g steps seed name
  "$LMP" -in "$here/validation/fpm/in.fpm_periodic_drag" -var plugin "$PLUGIN" \
    -var potentials "$here/potentials" -var out "field_$5" -var L 8 -var l "$1" -var g "$2" \
    -var u0 0.6 -var equil 15000 -var steps "$3" -var seed "$4" -var field yes \
    -log "log.field_$5" -screen none
}
if [ "$what" = all ] || [ "$what" = first ]; then
  run 0 0.00812 100000 4417 l0 & run 1.0 0.01442 200000 4418 l1.0 & wait
  run 1.5 0.01554 200000 4419 l1.5 & run 2.0 0.01615 200000 4420 l2.0 & wait
fi
if [ "$what" = all ] || [ "$what" = repeats ]; then
  for pair in "4431 4432" "4433 4434" "4435 4436" "4437 4438"; do
    set -- $pair
    run 1.5 0.01554 200000 "$1" "l1.5_s$1" & run 1.5 0.01554 200000 "$2" "l1.5_s$2" & wait
  done
fi
if [ "$what" = all ] || [ "$what" = axial ]; then
  # one colloid, its flow in rings about the stream's axis (400,000 steps, about 8 CPU-minutes)
  "$LMP" -in "$here/validation/fpm/in.fpm_periodic_drag" -var plugin "$PLUGIN" \
    -var potentials "$here/potentials" -var out axial_l0 -var L 8 -var l 0 -var g 0.00812 \
    -var u0 0.6 -var equil 15000 -var steps 400000 -var seed 4450 -var axial yes \
    -log log.axial_l0 -screen none
fi
repeats=() fields=()
for f in field_l1.5_s*.drag; do
  [ -f "$f" ] || continue
  repeats+=(--pair "l = 1.5, seed $(basename "${f#field_l1.5_s}" .drag)" "$f" 8 0.01554 1534 1.5)
  fields+=(--pair 1.5 "${f%.drag}.field" "$f")
done
# the stream the lone colloid meets: its drag N g over 6 pi mu R (mu, R of the paper)
stream=$(awk 'BEGIN { printf "%.5f", 1535 * 0.00812 / (6 * 3.14159265 * 3.6388 * 0.2737) }')
{
  /usr/bin/python3 "$here/python/fpm_torque_field.py" --lone field_l0.field --axial axial_l0.axial "$stream" \
    --pair 1.0 field_l1.0.field field_l1.0.drag --pair 1.5 field_l1.5.field field_l1.5.drag \
    --pair 2.0 field_l2.0.field field_l2.0.drag "${fields[@]}"
  /usr/bin/python3 "$here/python/fpm_analysis.py" . --pair "field run, l = 1" field_l1.0.drag 8 0.01442 1534 1.0 \
    --pair "field run, l = 1.5" field_l1.5.drag 8 0.01554 1534 1.5 \
    --pair "field run, l = 2" field_l2.0.drag 8 0.01615 1534 2.0 "${repeats[@]}"
  # every independent run in the cube of side 8 (those of two_spheres.sh too), weighted
  pairs=../two_spheres
  /usr/bin/python3 "$here/python/fpm_torque_field.py" \
    --runs 1.0 0.01442 $pairs/pair_L8_l1.drag $pairs/pair_L8_l1_s2.drag field_l1.0.drag \
    --runs 1.5 0.01554 $pairs/pair_L8_l1.5.drag field_l1.5.drag field_l1.5_s*.drag \
    --runs 2.0 0.01615 $pairs/pair_L8_l2.drag field_l2.0.drag
} | tee summary.txt

#!/usr/bin/env bash
# Long validation of pair_style dpd/fpm (not part of CI) against Pan, Pivkin and Karniadakis,
# EPL 84, 10012 (2008): fluid viscosity by reverse Poiseuille flow, the colloid's
# Stokes-Einstein radius from its diffusion, and the torque on a sphere spun at a fixed angular
# velocity. Reduced sizes by default (about 5 CPU-minutes each on one core); the paper's run
# lengths are not known, see doc/pair_dpd_fpm.rst. Results: out/fpm/results.md.
#
#   validation/fpm/run.sh [lammps executable]
# Environment: FPM_STEPS_SCALE (default 1) multiplies every production length;
# FPM_TORQUE_SCAN=1 adds short rotating-sphere runs (100 time units each, Omega = -6 unless
# stated) that separate the time step, the sign and size of Omega, the fluid's moment of inertia
# (fluid diameter 2; diameter 0.5 is unstable at dt = 0.01) and the neighbour-list delay
# (about 10 CPU-minutes in all).
# FPM_DRAG=1 adds the fixed colloid in a body-force-driven periodic cube (drag against
# 6 pi mu u R with Hasimoto's periodic-array correction; L = 6, 5,000 time units, and the
# paper's L = 10), FPM_COUETTE=1 the fixed and freely spinning colloids in Couette flow between
# walls (paper Table 1, box 15 x 6 x 8, 2,000 time units), FPM_POISEUILLE=1 the fixed colloid
# 2 from a wall in Poiseuille flow (paper Table 2, same box), FPM_PAIR=1 two fixed colloids
# 1 apart across a uniform flow in periodic cubes of side 8 and 10 (paper Table 3, reduced box);
# see validation/fpm/README.md.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
LMP=${1:-${LMP:-}}
. "$here/tools/lammps_env.sh"
lmp=$LMP
scale=${FPM_STEPS_SCALE:-1}
out="$here/out/fpm"; mkdir -p "$out"; cd "$out"
# a private copy: rebuilding the plugin while these runs go on does not touch them
cp "$PLUGIN" "$out/etddpdplugin.so"
common=(-var plugin "$out/etddpdplugin.so" -var potentials "$here/potentials" -screen none)
run() {    # name steps
  local name=$1 steps=$(( $2 * scale ))
  echo "running $name ($steps steps)"
  nice -n 10 "$lmp" -in "$here/validation/fpm/in.fpm_$name" "${common[@]}" -var steps "$steps" \
    -log "log.$name" >/dev/null
  grep -h RESULT "log.$name" | tail -1
}
run viscosity 20000 &
run diffusion 50000 &
wait
run rotating_sphere 60000
scan_args=()
if [[ "${FPM_TORQUE_SCAN:-0}" == 1 ]]; then
  scan() {    # label Omega dt fluid_diameter neigh_delay
    local name="scan_$1" per_unit
    per_unit=$(awk -v dt="$3" 'BEGIN { printf "%d", 1 / dt }')
    echo "running $name"
    nice -n 10 "$lmp" -in "$here/validation/fpm/in.fpm_rotating_sphere" "${common[@]}" -var out "$name" \
      -var Omega "$2" -var dt "$3" -var fluid_diameter "$4" -var neigh_delay "$5" \
      -var equil $(( 20 * per_unit )) -var steps $(( 100 * per_unit * scale )) -log "log.$name" >/dev/null
    scan_args+=(--torque "$1 (dt $3, fluid diameter $4, neigh_modify delay $5)" "$name.torque" "$2")
  }
  scan reference -6.0 0.01 1.0 0
  scan delay10 -6.0 0.01 1.0 10
  scan dt0.005 -6.0 0.005 1.0 0
  scan dt0.0025 -6.0 0.0025 1.0 0
  scan reversed 6.0 0.01 1.0 0
  scan omega12 -12.0 0.01 1.0 0
  scan inertia -6.0 0.01 2.0 0
fi
extra() {    # name input steps [-var ...]: one run of validation/fpm/in.fpm_<input>
  local name=$1 input=$2 steps=$(( $3 * scale )); shift 3
  echo "running $name ($steps steps)"
  nice -n 10 "$lmp" -in "$here/validation/fpm/in.fpm_$input" "${common[@]}" -var out "$name" \
    -var steps "$steps" "$@" -log "log.$name" >/dev/null
  grep -h RESULT "log.$name" | tail -1
}
if [[ "${FPM_DRAG:-0}" == 1 ]]; then
  extra drag_L6 periodic_drag 500000 -var L 6 -var g 0.0133 -var u0 0.4 -var equil 5000
  scan_args+=(--drag "L = 6" drag_L6.drag 6 0.0133 647)
  extra drag_L10 periodic_drag 200000 -var L 10 -var g 0.00271 -var u0 0.4 -var equil 30000
  scan_args+=(--drag "L = 10" drag_L10.drag 10 0.00271 2999)
fi
if [[ "${FPM_COUETTE:-0}" == 1 ]]; then
  extra couette_U8 wall_channel 200000 -var flow couette -var U 8.0
  scan_args+=(--couette "wall speed 8, 2 fixed + 2 free colloids" couette_U8 8)
  extra couette_U8_d2 wall_channel 200000 -var flow couette -var U 8.0 -var colloid_diameter 2.0
  scan_args+=(--couette "same, colloid moment of inertia x 4" couette_U8_d2 8)
fi
if [[ "${FPM_POISEUILLE:-0}" == 1 ]]; then
  extra poiseuille_g0.2 wall_channel 200000 -var flow poiseuille -var g 0.2 -var h 2.0
  scan_args+=(--poiseuille "h = 2" poiseuille_g0.2 0.2 8 2)
  extra poiseuille_g0.05 wall_channel 200000 -var flow poiseuille -var g 0.05 -var h 2.0
  scan_args+=(--poiseuille "h = 2" poiseuille_g0.05 0.05 8 2)
fi
if [[ "${FPM_PAIR:-0}" == 1 ]]; then
  extra pair_l1 periodic_drag 400000 -var L 8 -var l 1.0 -var g 0.01442 -var u0 0.6 -var equil 15000
  scan_args+=(--pair "L = 8" pair_l1.drag 8 0.01442 1534 1.0)
  extra pair_l1_slow periodic_drag 400000 -var L 8 -var l 1.0 -var g 0.00805 -var u0 0.335 -var equil 15000
  scan_args+=(--pair "L = 8, paper's u" pair_l1_slow.drag 8 0.00805 1534 1.0)
  extra pair_l1_L10 periodic_drag 200000 -var L 10 -var l 1.0 -var g 0.0071 -var u0 0.6 -var equil 10000
  scan_args+=(--pair "L = 10" pair_l1_L10.drag 10 0.0071 2998 1.0)
fi
/usr/bin/python3 "$here/python/fpm_analysis.py" "$out" "${scan_args[@]}" | tee "$out/results.md"

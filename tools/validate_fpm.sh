#!/usr/bin/env bash
# Long validation of pair_style dpd/fpm (not part of CI) against Pan, Pivkin and Karniadakis,
# EPL 84, 10012 (2008): fluid viscosity by reverse Poiseuille flow, the colloid's
# Stokes-Einstein radius from its diffusion, and the torque on a sphere spun at a fixed angular
# velocity. Reduced sizes by default (about 5 CPU-minutes each on one core); the paper's run
# lengths are not known, see doc/pair_dpd_fpm.rst. Results: out/fpm/results.md.
#
#   tools/validate_fpm.sh [lammps executable]
# Environment: FPM_STEPS_SCALE (default 1) multiplies every production length.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
lmp=${1:-}
if [[ -z "$lmp" ]]; then
  prefix=$(bash "$here/tools/bootstrap.sh" 2>/dev/null | sed -n 's/^LAMMPS_PREFIX=//p')
  lmp="$prefix/bin/lmp"
fi
scale=${FPM_STEPS_SCALE:-1}
out="$here/out/fpm"; mkdir -p "$out"; cd "$out"
# a private copy: rebuilding the plugin while these runs go on does not touch them
cp "$here/build/etddpd.so" "$out/etddpd.so"
common=(-var plugin "$out/etddpd.so" -var potentials "$here/potentials" -screen none)
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
/usr/bin/python3 "$here/tools/fpm_analysis.py" "$out" | tee "$out/results.md"

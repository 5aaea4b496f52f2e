#!/usr/bin/env bash
# Long physics validation (not part of CI): self-diffusion (MSD and VACF) and the Schmidt number
# against mass, side by side with Mai-Duy, Phan-Thien and Tran-Cong (2013), Table 1
# (validation/diffusion/in.diffusion; 4,000 atoms, n = 4, a = 18.75, gamma = 4.5, s = 1/2, kBT = 1).
# Integrators: velocity-Verlet (dpd/gen + nve) where its step is affordable, the implicit scheme
# of fix etd at low mass. About 10 minutes on one core; writes validation/diffusion/README.md.
# Usage: bash validation/diffusion/run.sh [MSD time units, default 4]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
time_units=${1:-4}
out="$here/out/validation_diffusion"; mkdir -p "$out"
rows=()
run() {    # mass dt integrator VACF-window VACF-origins [measured eta]
  local dir="$out/m$1_${3%% *}_$2"; mkdir -p "$dir"
  (cd "$dir" && "$LMP" -in "$here/validation/diffusion/in.diffusion" -var plugin "$PLUGIN" \
    -var mass "$1" -var dt "$2" -var integrator "$3" -var time "$time_units" \
    -var vacf_time "$4" -var origins "$5" -log log.lammps -screen none)
  grep RESULT "$dir/log.lammps" | tail -1
  rows+=("$dir:$1:$2:$3:${6:-}")
}
# the VACF window shrinks with the mass (the velocity relaxes in about m/gamma, while the noise of
# a window's integral grows with its length and with kBT/m); more origins make up for it
run 1.0 0.01 nve 1.0 4
run 0.1 0.002 nve 0.5 4
run 0.01 0.002 "etd scheme implicit" 0.1 10 1.948
run 0.001 0.0005 "etd scheme implicit" 0.03 20 1.909
# the paper's diagonal scheme at a step that resolves m/gamma, as the paper ran it
run 0.01 0.0005 etd 0.1 10 1.948
run 0.001 0.00005 etd 0.03 20 1.909
{
  echo "# Self-diffusion and Schmidt number against mass"
  echo
  echo "Command: \`bash validation/diffusion/run.sh $time_units\`. Periodic box of 4,000 atoms, n = 4, a = 18.75,"
  echo "gamma = 4.5 (sigma = 3), s = 1/2, kBT = 1 (\`validation/diffusion/in.diffusion\`), 1 time unit of"
  echo "equilibration. D (MSD): slope of the mean-square displacement / 6 over the second half of a"
  echo "$time_units-unit run (centre of mass removed). D (VACF): Green-Kubo integral of the velocity"
  echo "autocorrelation over a window of 1 (m = 1), 0.5 (m = 0.1), 0.1 (m = 0.01) or 0.03 (m = 0.001) time units, mean and standard error over 4, 4, 10 and 20 successive time origins. Sc = eta/(rho D),"
  echo "rho = m n, with the kinetic-theory viscosity of this fluid (2.2282 + 0.1741 m, what the paper's"
  echo "Sc values imply) and with the viscosity measured by reverse Poiseuille flow"
  echo "(validation/implicit/README.md: 1.948 at m = 0.01, 1.909 at m = 0.001). Paper: Mai-Duy,"
  echo "Phan-Thien and Tran-Cong (J. Rheol. 2013), Table 1."
  echo
  /usr/bin/python3 "$here/python/diffusion_table.py" "${rows[@]}"
} >"$here/validation/diffusion/README.md"
cat "$here/validation/diffusion/README.md"

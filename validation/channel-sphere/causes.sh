#!/bin/bash
# Runs that test candidate causes of the gap between the 56-particle sphere's C_D and the
# Brown-Lawler correlation (README section 6): the paper's length along the flow with profiles
# around the sphere (shell means of density and v_x: slip and hydrodynamic radius), and the
# reduced box at half the paper's step (the integrator's share). Output in results/.
# Run from anywhere: bash validation/channel-sphere/causes.sh  (about 45 minutes on one core)
# The viscosity runs are viscosity.sh.
set -e
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/../../tools/lammps_env.sh"
cd "$here/results"
cp "$PLUGIN" ./causes_plugin.so    # a private copy: rebuilds do not touch the running jobs
input=$here/../../examples/channel-sphere/in.sphere_shear
"$LMP" -in "$input" -var plugin ./causes_plugin.so -var U 0.9 -var nx 120 -var steps 12000 \
  -var profiles yes -var label U0.9_nx120_profiles -log log.sphere_shear_U0.9_nx120_profiles.g++.1 -screen none
"$LMP" -in "$input" -var plugin ./causes_plugin.so -var U 0.9 -var dt 0.005 -var equil 4000 -var steps 50000 \
  -var label U0.9_dt0.005 -log log.sphere_shear_U0.9_dt0.005.g++.1 -screen none
rm -f ./causes_plugin.so

#!/usr/bin/env bash
# Long physics validation of fix etd scheme implicit (not part of CI): temperature, reverse-
# Poiseuille viscosity and self-diffusion against time step at m = 0.01 and 0.001, velocity-
# Verlet at a small step as the reference, and m = 0.0001 towards the zero-mass limit. About
# 25 minutes on 2 cores with the defaults; writes validation/implicit/results.md and
# results.jsonl. Usage: bash validation/implicit/run.sh [--time T] [--seeds N] [--jobs J]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
export LMP PLUGIN
exec /usr/bin/python3 "$here/validation/implicit/run.py" "$@"

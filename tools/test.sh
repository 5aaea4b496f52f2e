#!/usr/bin/env bash
# Set everything up (Debian packages, LAMMPS, plugin) and run the default test suite:
# unit, integration and MPI tests (1, 2 and 4 ranks). Long physics validation is separate:
# tools/validate.sh. Extra arguments go to ctest (e.g. -R pair -V).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/tools/bootstrap.sh" >/dev/null
cd "$here/build"
# MPI tests may oversubscribe the cores; run tests one at a time so timings stay sane
ctest --output-on-failure -LE validation "$@"

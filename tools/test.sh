#!/usr/bin/env bash
# Set everything up (Debian packages, LAMMPS, plugin) and run the default test suite:
# unit, integration and MPI tests (1, 2 and 4 ranks) and the doc build. Long physics validation
# is separate: validation/temperature/run.sh. Extra arguments go to ctest (e.g. -R pair -V).
# ETD_DPD_LAMMPS=sid selects Debian's newest LAMMPS source instead of 29Sep2021 (see bootstrap.sh).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(bash "$here/tools/bootstrap.sh" | sed -n 's/^ETD_DPD_BUILD=//p')
cd "$build"
printf '[etd-dpd] testing against LAMMPS %s\n' "$(sed -n 's/.*lammps-\([^-]*\)-.*/\1/p' lammps-prefix)" >&2
ctest --output-on-failure -LE validation "$@"

#!/bin/bash
# The kernel and solver tests build and pass from a configuration with no LAMMPS prefix (no
# LAMMPS library to link): check_kernel_tests.sh SOURCE LAMMPS_SOURCE_DIR BUILD "TEST ..."
set -euo pipefail
src=$1 lammps_src=$2 build=$3 tests=$4
cmake -S "$src" -B "$build" -D CMAKE_BUILD_TYPE=Release -D LAMMPS_SOURCE_DIR="$lammps_src" \
      -D LAMMPS_PREFIX= >"$build.configure.log" 2>&1 || { cat "$build.configure.log"; exit 1; }
if grep -q "LAMMPS::lammps" "$build/CMakeCache.txt"; then
  echo "the kernel-only configuration found a LAMMPS library" >&2
  exit 1
fi
# shellcheck disable=SC2086
cmake --build "$build" -j 2 --target $tests >"$build.build.log" 2>&1 || { tail -40 "$build.build.log"; exit 1; }
cd "$build"
# shellcheck disable=SC2086
ctest --output-on-failure -R "^($(echo $tests | tr ' ' '|'))(_np[0-9]+)?\$"

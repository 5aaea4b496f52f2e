#!/usr/bin/env bash
# The KOKKOS test leg: the package built with its /kk styles (ETD_DPD_KOKKOS=ON) against the
# KOKKOS LAMMPS of build_lammps_kokkos.sh (OpenMP and Serial backends, one shared Kokkos), and
# the default suite on it (what tools/test.sh runs, on a third LAMMPS version) with the tests
# labelled kokkos (unittest/test_kokkos_styles.cpp on 1 and 2 ranks x 1 and 2 threads).
# Not part of .ci/run: Debian ships no Kokkos source that a KOKKOS LAMMPS of a supported version
# builds against (tools/kokkos/README.md), so KOKKOS_SOURCE must name an unpacked Kokkos release.
# Run it in every session that touches src/KOKKOS or the pair loop.
#   KOKKOS_SOURCE=/path/to/kokkos-4.6.1 ETD_DPD_LAMMPS=trixie tools/kokkos/test.sh [ctest args]
#   ETD_DPD_KOKKOS_AS_5=1 KOKKOS_SOURCE=/path/to/kokkos-4.6.1 ETD_DPD_KOKKOS_BUILD=$PWD/build-kokkos-sid \
#     tools/kokkos/test.sh          (LAMMPS 4Jul2026, Kokkos 4.6.1 standing in for 5)
# Environment: as build_lammps_kokkos.sh (ETD_DPD_KOKKOS_BACKEND=cuda: the package compiled with
# that Kokkos's nvcc_wrapper, and the KOKKOS tests on 1 and 2 ranks sharing one GPU), and
#   ETD_DPD_KOKKOS_BUILD   build folder (default ./build-kokkos, ./build-kokkos-cuda for cuda)
#   ETD_DPD_CMAKE_ARGS     more arguments for the package's configure (where GTest, Boost or
#                          Random123 are not installed: tools/kokkos/gpu.sh passes its own)
#   ETD_DPD_BUILD_TARGETS  build these targets alone (default: all)
# Extra arguments go to ctest (-L kokkos: the KOKKOS tests alone). Prints the LAMMPS it tested
# against and ctest's summary; exits non-zero on a failure.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
prefix=$(bash "$here/tools/kokkos/build_lammps_kokkos.sh" | sed -n 's/^LAMMPS_KOKKOS_PREFIX=//p')
[ -f "$prefix/.complete" ] || { echo "no complete KOKKOS LAMMPS at $prefix" >&2; exit 1; }
backend=${ETD_DPD_KOKKOS_BACKEND:-openmp}
build_default=$here/build-kokkos
compiler=() cxx=
if [ "$backend" = cuda ]; then
  build_default=$here/build-kokkos-cuda
  cxx=$(cat "$prefix/kokkos-source-dir")/bin/nvcc_wrapper
  compiler=(-D CMAKE_CXX_COMPILER="$cxx")
  # the toolkit's libcuda stub, where the machine has no GPU driver (build_lammps_kokkos.sh)
  if [ -d "$prefix/cuda-stubs" ]; then
    compiler+=(-D CMAKE_EXE_LINKER_FLAGS="-Wl,-rpath-link,$prefix/cuda-stubs")
  fi
fi
build=${ETD_DPD_KOKKOS_BUILD:-$build_default}
read -r -a extra_cmake <<<"${ETD_DPD_CMAKE_ARGS:-}"
# an installed Kokkos that this LAMMPS links (build_lammps_kokkos.sh, ETD_DPD_KOKKOS_INSTALLED)
[ ! -f "$prefix/kokkos-dir" ] || extra_cmake+=(-D ETD_DPD_KOKKOS_DIR="$(cat "$prefix/kokkos-dir")")
targets=()
for target in ${ETD_DPD_BUILD_TARGETS:-}; do targets+=(--target "$target"); done
mkdir -p "$build"
# another compiler than the cached one (a CUDA prefix rebuilt elsewhere): CMake would drop the
# cache and rerun without this command's -D values, so the cache goes first
if [ -n "$cxx" ] && [ -f "$build/CMakeCache.txt" ] \
   && [ "$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")" != "$cxx" ]; then
  rm -rf "$build/CMakeCache.txt" "$build/CMakeFiles"
fi
cmake -S "$here" -B "$build" -D CMAKE_BUILD_TYPE=Release -D LAMMPS_SOURCE_DIR="$(cat "$prefix/source-dir")" \
      -D LAMMPS_PREFIX="$prefix" -D ETD_DPD_KOKKOS=ON "${compiler[@]}" "${extra_cmake[@]}" \
      >"$build/configure.log" 2>&1 \
  || { tail -30 "$build/configure.log" >&2; exit 1; }
cmake --build "$build" -j "${ETD_DPD_JOBS:-$(nproc)}" "${targets[@]}" >"$build/build.log" 2>&1 || { grep -E "error|Error" -A5 "$build/build.log" | head -40 >&2; exit 1; }
printf '[etd-dpd] KOKKOS leg: LAMMPS %s, Kokkos %s (%s)\n' \
  "$(sed -n 's/.*lammps-kokkos-\([^-]*\)-.*/\1/p' <<<"$prefix")" \
  "$(sed -n 's/.*KOKKOS styles against Kokkos \([^ ]*\).*/\1/p' "$build/configure.log")" "$prefix" >&2
cd "$build"
ctest --output-on-failure -LE validation "$@"

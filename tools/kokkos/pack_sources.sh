#!/usr/bin/env bash
# Pack what tools/kokkos/gpu.sh needs on a machine that reaches no network into one ignored
# folder (default ./build-gpu-sources), small enough to travel with the working tree:
#   kokkos.tar.xz   the Kokkos source without its tests and docs
#   lammps.tar.xz   the LAMMPS source that CMake reads for the CUDA build (build_lammps_kokkos.sh,
#                   ETD_DPD_KOKKOS_BACKEND=cuda): cmake/, src/ (its files, fmt/ and the packages
#                   KOKKOS, DPD-BASIC, DPD-REACT, PLUGIN and STUBS), doc/lammps.1, and empty
#                   potentials/ and bench/
#                   (LAMMPS installs both folders)
#   deps.tar.xz     headers and sources the package's build needs where the machine lacks them:
#                   Random123, the Boost headers that its Boost includes reach (and all of
#                   boost/config), GoogleTest's source
#   openmpi.tar.xz  Debian's Open MPI and what it loads, for a machine without MPI (Debian only)
# Usage: tools/kokkos/pack_sources.sh [OUT_DIR]      (prints each file's size and the total)
# Environment: KOKKOS_SOURCE (an unpacked Kokkos release), LAMMPS_SOURCE or ETD_DPD_LAMMPS (the
# Debian suite whose LAMMPS source tools/debian_lammps_source.sh fetched, as build_lammps_kokkos.sh),
# ETD_DPD_CACHE, GTEST_SOURCE (default /usr/src/googletest).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${1:-$here/build-gpu-sources}
cache=${ETD_DPD_CACHE:-$HOME/.cache/etd-dpd}
die() { printf '[etd-dpd] ERROR: %s\n' "$*" >&2; exit 1; }
[ -n "${KOKKOS_SOURCE:-}" ] || die "set KOKKOS_SOURCE to an unpacked Kokkos release"
ksrc=$(cd "$KOKKOS_SOURCE" && pwd)
if [ -n "${LAMMPS_SOURCE:-}" ]; then lsrc=$(cd "$LAMMPS_SOURCE" && pwd)
else lsrc="$cache/src-${ETD_DPD_LAMMPS:-sid}/lammps"; fi
[ -f "$lsrc/src/version.h" ] || die "no LAMMPS source at $lsrc (set LAMMPS_SOURCE or ETD_DPD_LAMMPS)"
gtest=${GTEST_SOURCE:-/usr/src/googletest}
[ -f "$gtest/CMakeLists.txt" ] || die "no GoogleTest source at $gtest (Debian: googletest; or set GTEST_SOURCE)"
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Kokkos: CMake reads the test folders only when tests are enabled (example/ and benchmarks/
# always)
tar -C "$(dirname "$ksrc")" -cJf "$out/kokkos.tar.xz" \
  --exclude="*/unit_test" --exclude="*/unit_tests" --exclude="*/perf_test" \
  --exclude="$(basename "$ksrc")/doc" --exclude="$(basename "$ksrc")/.git" \
  --transform "s,^$(basename "$ksrc"),kokkos," "$(basename "$ksrc")"

# LAMMPS: the top of src/ and the packages that the CUDA build enables
mkdir -p "$work/lammps/src" "$work/lammps/doc" "$work/lammps/potentials" "$work/lammps/bench"
cp -a "$lsrc/cmake" "$work/lammps/"
find "$lsrc/src" -maxdepth 1 -type f -exec cp -a {} "$work/lammps/src/" \;
find "$lsrc/src" -mindepth 1 -maxdepth 1 -type d -name '[a-z]*' -exec cp -a {} "$work/lammps/src/" \;  # fmt/
for package in KOKKOS DPD-BASIC DPD-REACT PLUGIN STUBS; do cp -a "$lsrc/src/$package" "$work/lammps/src/"; done
# KOKKOS styles that neither the tests nor the benchmark use, and that no kept KOKKOS source
# includes: LAMMPS registers a /kk style only where its files are present, and nvcc spends
# 20-60 s on each of these
for style in pair_buck pair_buck_coul_cut pair_coul_cut pair_coul_debye pair_coul_dsf \
             pair_coul_wolf pair_exp6_rx pair_lj_cut pair_lj_cut_coul_cut pair_lj_expand \
             pair_morse pair_multi_lucy_rx pair_soft pair_table pair_table_rx pair_yukawa pair_zbl \
             pair_dpd_ext pair_dpd_ext_tstat pair_dpd_tstat fix_rx fix_eos_table_rx fix_efield \
             fix_gravity fix_spring_self fix_wall_lj93 fix_wall_reflect fix_wall_region \
             fix_nvt_sllod fix_recenter fix_viscous fix_temp_berendsen fix_temp_rescale \
             fix_dt_reset fix_enforce2d fix_nve_limit compute_orientorder_atom compute_coord_atom \
             region_sphere; do
  rm -f "$work/lammps/src/KOKKOS/${style}_kokkos.cpp" "$work/lammps/src/KOKKOS/${style}_kokkos.h"
done
cp -a "$lsrc/doc/lammps.1" "$work/lammps/doc/"
tar -C "$work" -cJf "$out/lammps.tar.xz" lammps

# deps: Random123, the Boost headers reached from the ones the package includes, GoogleTest
mkdir -p "$work/deps/include" "$work/deps/googletest"
cp -a /usr/include/Random123 "$work/deps/include/"
grep -rhoE '#include <boost/[^>]+>' "$here/src" "$here/unittest" | sort -u >"$work/boost.cpp"
g++ -std=c++17 -M -x c++ "$work/boost.cpp" | tr ' ' '\n' | grep -E '^/usr/include/boost/' | sort -u \
  | sed 's,^/usr/include/,,' >"$work/boost.list"
echo boost/config >>"$work/boost.list"
(cd /usr/include && tar -cf - -T "$work/boost.list") | tar -C "$work/deps/include" -xf -
cp -a "$gtest/." "$work/deps/googletest/"
tar -C "$work" -cJf "$out/deps.tar.xz" deps

# openmpi: Debian's Open MPI (runtime, wrappers, headers) with PMIx and the libraries they load,
# at their own paths, for a machine without MPI. The package and LAMMPS link libmpi.so.40, so a
# build made here runs there with it; gpu.sh unpacks it only where no file is already in place.
{
  dpkg -L openmpi-bin libopenmpi3 openmpi-common libopenmpi-dev libpmix2 \
    | grep -v -E '/share/(doc|man)/|lintian|java|fortran|/usr/bin/(mpif|osh|shmem)|oshmem'
  for tool in mpirun mpiexec mpicxx mpic++ mpicc; do echo "/usr/bin/$tool"; echo "/etc/alternatives/$tool"; done
} | while read -r f; do if [ -L "$f" ] || [ -f "$f" ]; then echo "$f"; fi; done | sort -u >"$work/mpi.list"
grep -E '\.so' "$work/mpi.list" | while read -r f; do ldd "$f" 2>/dev/null | awk '/=> \//{print $3}'; done \
  | sort -u | grep -v -E '/(libc|libm|libgcc_s|libstdc\+\+|libpthread|libdl|librt)\.so' \
  | while read -r lib; do echo "$lib"; readlink -f "$lib"; done | sort -u >>"$work/mpi.list"
tar -cJf "$out/openmpi.tar.xz" -P -T "$work/mpi.list"

du -b "$out"/*.tar.xz | awk '{printf "%-40s %6.1f MiB\n", $2, $1 / 1048576; t += $1}
                             END {printf "%-40s %6.1f MiB\n", "total", t / 1048576}'

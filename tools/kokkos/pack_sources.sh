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

du -b "$out"/*.tar.xz | awk '{printf "%-40s %6.1f MiB\n", $2, $1 / 1048576; t += $1}
                             END {printf "%-40s %6.1f MiB\n", "total", t / 1048576}'

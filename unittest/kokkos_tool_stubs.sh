# Sourced by the KOKKOS tools' tests (check_kokkos_tool_errors.sh, check_kokkos_prefix_keys.sh):
# stub source trees with only the files build_lammps_kokkos.sh reads before it builds anything.
# stub_lammps DIR MAJOR: a LAMMPS 4Jul2026 whose KOKKOS package asks find_package(Kokkos MAJOR.1.0)
stub_lammps() {
  mkdir -p "$1/src" "$1/cmake/Modules/Packages"
  echo '#define LAMMPS_VERSION "4 Jul 2026"' >"$1/src/version.h"
  echo "  find_package(Kokkos $2.1.0 REQUIRED CONFIG)" >"$1/cmake/Modules/Packages/KOKKOS.cmake"
}
# stub_kokkos DIR: a Kokkos 4.6.1
stub_kokkos() {
  mkdir -p "$1"
  printf 'set(Kokkos_VERSION_MAJOR 4)\nset(Kokkos_VERSION_MINOR 6)\nset(Kokkos_VERSION_PATCH 1)\n' \
    >"$1/CMakeLists.txt"
}

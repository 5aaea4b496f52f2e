#!/usr/bin/env bash
# Build the KOKKOS plugin probe (tools/kokkos/probe) against the KOKKOS LAMMPS of
# build_lammps_kokkos.sh and run it: `plugin load` into lmp -k on t 2 -sf kk, 100 steps of a DPD
# fluid with pair_style dpd/probe (-> dpd/probe/kk from the plugin), compared line by line with
# LAMMPS's own dpd/kk (same kernels, same seed: the thermo output must be identical), then the
# same run on 2 MPI ranks x 1 thread, then under valgrind (no invalid free / double free at exit).
#   tools/kokkos/probe.sh [PREFIX]     PREFIX: the KOKKOS LAMMPS (default: build it / reuse it)
# Environment: ETD_DPD_LAMMPS, KOKKOS_SOURCE (passed to build_lammps_kokkos.sh),
#              ETD_DPD_PROBE_BUILD (default ./build-kokkos-probe), ETD_DPD_VALGRIND=0 to skip valgrind
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
prefix=${1:-}
if [ -z "$prefix" ]; then
  prefix=$("$here/build_lammps_kokkos.sh" | sed -n 's/^LAMMPS_KOKKOS_PREFIX=//p')
fi
[ -f "$prefix/.complete" ] || { echo "no complete KOKKOS LAMMPS at $prefix" >&2; exit 1; }
src=$(cat "$prefix/source-dir")
build=${ETD_DPD_PROBE_BUILD:-$(pwd)/build-kokkos-probe}
mkdir -p "$build"
cmake -S "$here/probe" -B "$build" -D CMAKE_BUILD_TYPE=Release -D LAMMPS_SOURCE_DIR="$src" \
      -D LAMMPS_KOKKOS_PREFIX="$prefix" >"$build/probe-configure.log" 2>&1 \
  || { tail -30 "$build/probe-configure.log" >&2; exit 1; }
grep "probe: Kokkos" "$build/probe-configure.log"
cmake --build "$build" -j "$(nproc)" >"$build/probe-build.log" 2>&1 || { tail -30 "$build/probe-build.log" >&2; exit 1; }
plugin="$build/dpdprobekkplugin.so"
echo "== shared libraries of the plugin and of liblammps (one Kokkos) =="
ldd "$plugin" | grep -i kokkos
ldd "$prefix/lib/liblammps.so" | grep -i kokkos
lmp="$prefix/bin/lmp"
export OMP_PROC_BIND=spread OMP_PLACES=threads
run() {  # NAME ARGS...: runs lmp, keeps log, stdout, stderr, exit status
  local name=$1; shift
  set +e
  "$@" -log "$build/log.$name" >"$build/out.$name" 2>"$build/err.$name"
  local rc=$?
  set -e
  echo "== $name: exit status $rc, stderr: $(wc -l <"$build/err.$name") lines =="
  cat "$build/err.$name" >&2
  return $rc
}
fail=0
run plugin "$lmp" -k on t 2 -sf kk -var style dpd/probe -var load 1 -var plugin "$plugin" -in "$here/probe/in.dpd_probe" || fail=1
run builtin "$lmp" -k on t 2 -sf kk -var style dpd -in "$here/probe/in.dpd_probe" || fail=1
if command -v mpirun >/dev/null; then
  mpiflags=(); [ "$(id -u)" = 0 ] && mpiflags+=(--allow-run-as-root)
  run plugin-2ranks mpirun "${mpiflags[@]}" --oversubscribe -np 2 "$lmp" -k on t 1 -sf kk \
    -var style dpd/probe -var load 1 -var plugin "$plugin" -in "$here/probe/in.dpd_probe" || fail=1
fi
grep -E "Loading plugin|pair style plugin|Kokkos::OpenMP|dpd/probe" "$build/out.plugin" || true
thermo() { awk '/^ *Step/{t=1} t&&/^Loop/{t=0} t' "$1"; }
thermo "$build/out.plugin"
if diff <(thermo "$build/out.plugin") <(thermo "$build/out.builtin") >/dev/null; then
  echo "thermo output of dpd/probe/kk (plugin) and dpd/kk (liblammps): identical"
else
  echo "thermo output of dpd/probe/kk (plugin) and dpd/kk (liblammps): DIFFERENT"; fail=1
  diff <(thermo "$build/out.plugin") <(thermo "$build/out.builtin") || true
fi
if [ "${ETD_DPD_VALGRIND:-1}" != 0 ] && command -v valgrind >/dev/null; then
  set +e
  valgrind --error-exitcode=1 --log-file="$build/valgrind.log" "$lmp" -k on t 2 -sf kk \
    -var style dpd/probe -var load 1 -var plugin "$plugin" -in "$here/probe/in.dpd_probe" -log none \
    >"$build/out.valgrind" 2>&1
  vrc=$?
  set -e
  echo "== valgrind: exit status $vrc =="
  grep -E "ERROR SUMMARY|Invalid free|double free|definitely lost" "$build/valgrind.log" || true
  if grep -qE "Invalid free|double free|free\(\): invalid" "$build/valgrind.log" "$build/out.valgrind"; then
    echo "valgrind: invalid free at exit"; fail=1
  fi
fi
# the negative control (ETD_DPD_PROBE_STATIC_CONTROL=1): the same plugin with its own static
# Kokkos linked in; valgrind is expected to report an invalid free at exit (the double free of
# LAMMPS issue 3469: Kokkos' global objects destroyed once per copy)
if [ "${ETD_DPD_PROBE_STATIC_CONTROL:-0}" = 1 ]; then
  ksrc=$(cat "$prefix/kokkos-source-dir"); ks="$build/kokkos-static"
  cmake -S "$ksrc" -B "$ks/build" -D CMAKE_BUILD_TYPE=Release -D BUILD_SHARED_LIBS=off \
        -D CMAKE_POSITION_INDEPENDENT_CODE=on -D CMAKE_CXX_STANDARD=20 -D CMAKE_CXX_EXTENSIONS=off \
        -D Kokkos_ENABLE_OPENMP=on -D Kokkos_ENABLE_SERIAL=on -D Kokkos_ENABLE_IMPL_VIEW_LEGACY=on \
        -D CMAKE_INSTALL_PREFIX="$ks" -D CMAKE_INSTALL_LIBDIR=lib >"$ks.log" 2>&1
  cmake --build "$ks/build" -j "$(nproc)" >>"$ks.log" 2>&1 && cmake --install "$ks/build" >>"$ks.log" 2>&1
  mpicxx -std=c++20 -O2 -fPIC -fopenmp -shared -DLMP_KOKKOS -DLAMMPS_SMALLBIG -I"$src/src" \
    -I"$src/src/KOKKOS" -I"$src/src/DPD-BASIC" -I"$ks/include" "$here/probe/dpd_probe_kk.cpp" \
    -o "$build/static-kokkos-probe.so" "$ks/lib/libkokkoscontainers.a" "$ks/lib/libkokkoscore.a" -ldl
  set +e
  valgrind --error-exitcode=1 --log-file="$build/valgrind-static.log" "$lmp" -k on t 2 -sf kk \
    -var style dpd/probe -var load 1 -var plugin "$build/static-kokkos-probe.so" \
    -in "$here/probe/in.dpd_probe" -log none >/dev/null 2>&1
  echo "== control, static Kokkos in the plugin: valgrind exit status $? =="
  set -e
  grep -E -A3 "Invalid free|ERROR SUMMARY" "$build/valgrind-static.log" | head -8 || true
fi
[ "$fail" = 0 ] && echo "PROBE PASSED" || { echo "PROBE FAILED"; exit 1; }

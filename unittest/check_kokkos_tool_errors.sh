#!/usr/bin/env bash
# The KOKKOS tools stop with an ERROR that names the bad argument or setting, before they build
# or run anything: tools/kokkos/gpu.sh's arguments, bench/kokkos's run.sh and alternate.sh's
# arguments and settings, and build_lammps_kokkos.sh's backend and
# its LAMMPS/Kokkos pairing (a LAMMPS that asks for Kokkos 5 against a Kokkos 4.6 source,
# without ETD_DPD_KOKKOS_AS_5), and an installed Kokkos that is none or serves no such backend.
# The LAMMPS and Kokkos trees here are stubs with the files the script reads first; no network,
# no compiler.
set -uo pipefail
# the settings a caller may have exported (tools/kokkos/test.sh's own) would change the paths
unset ETD_DPD_KOKKOS_AS_5 ETD_DPD_KOKKOS_BACKEND ETD_DPD_KOKKOS_ARCH ETD_DPD_LAMMPS LAMMPS_SOURCE \
  KOKKOS_SOURCE ETD_DPD_KOKKOS_INSTALLED ETD_DPD_KOKKOS_SUITE ETD_DPD_GPU_SOURCES ETD_DPD_THREADS \
  ETD_DPD_KOKKOS_BUILD ETD_DPD_BENCH_SCHEME ETD_DPD_BENCH_OUT ETD_DPD_BENCH_BIND ETD_DPD_BENCH_APPEND
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
# expect_error WHAT PATTERN COMMAND...: the command exits non-zero with an ERROR line matching PATTERN
expect_error() {
  local what=$1 pattern=$2 out status; shift 2
  out=$("$@" 2>&1); status=$?
  if [ "$status" -ne 0 ] && grep -q "ERROR: .*$pattern" <<<"$out"; then
    echo "ok: $what"
  else
    echo "FAIL: $what (status $status): $out"; failures=$((failures + 1))
  fi
}
gpu=$root/tools/kokkos/gpu.sh
expect_error "gpu.sh unknown argument" "unknown argument --bogus" bash "$gpu" --bogus
expect_error "gpu.sh option without value" "--steps needs a value" bash "$gpu" --steps
expect_error "gpu.sh --until not a time" "--until abc" bash "$gpu" --until abc
expect_error "gpu.sh unknown phase" "unknown phase deploy" bash "$gpu" --phases build,deploy
expect_error "gpu.sh unknown case" "unknown case gen-nvt" bash "$gpu" --cases gen-nve,gen-nvt
expect_error "gpu.sh size not a number" "--sizes: 32k" bash "$gpu" --sizes 32000,32k
expect_error "gpu.sh zero steps" "--steps 0" bash "$gpu" --steps 0
expect_error "gpu.sh warmup not a number" "--warmup -5" bash "$gpu" --warmup -5
expect_error "gpu.sh timeout not a number" "--timeout 1m" bash "$gpu" --timeout 1m

# the benchmark drivers of bench/kokkos, before they look up the KOKKOS LAMMPS
alternate=$root/bench/kokkos/alternate.sh
: >"$work/plugin.so"
expect_error "alternate.sh without plugins" "usage: " bash "$alternate" 2 100
expect_error "alternate.sh rounds not a number" "ROUNDS two" bash "$alternate" two 100 "$work/plugin.so"
expect_error "alternate.sh zero steps" "STEPS 0" bash "$alternate" 2 0 "$work/plugin.so"
expect_error "alternate.sh missing plugin" "no plugin at $work/none.so" bash "$alternate" 2 100 "$work/none.so"
expect_error "alternate.sh sort not a number" "@often is no atom_modify sort period" \
  bash "$alternate" 2 100 "$work/plugin.so@often"
expect_error "alternate.sh unknown scheme" "ETD_DPD_BENCH_SCHEME=shardlow" \
  env ETD_DPD_BENCH_SCHEME=shardlow bash "$alternate" 2 100 "$work/plugin.so"
expect_error "alternate.sh output not .jsonl" "ETD_DPD_BENCH_OUT=$work/out.md" \
  env ETD_DPD_BENCH_OUT="$work/out.md" bash "$alternate" 2 100 "$work/plugin.so"
run=$root/bench/kokkos/run.sh
expect_error "run.sh rounds not a number" "ROUNDS 3x" bash "$run" 3x
expect_error "run.sh too many arguments" "usage: " bash "$run" 3 100 extra
expect_error "run.sh missing plugin" "no KOKKOS plugin at $work/none/etddpdplugin.so" \
  env ETD_DPD_KOKKOS_BUILD="$work/none" bash "$run" 1 10

# stub trees: a LAMMPS that asks find_package(Kokkos 5.1.0), a Kokkos 4.6.1
. "$root/unittest/kokkos_tool_stubs.sh"
stub_lammps "$work/lammps" 5
stub_kokkos "$work/kokkos"
build=$root/tools/kokkos/build_lammps_kokkos.sh
expect_error "build_lammps_kokkos.sh unknown argument" "unknown argument --bogus" bash "$build" --bogus
expect_error "build_lammps_kokkos.sh Kokkos 4.6 for a LAMMPS that asks for 5" \
  "LAMMPS 4Jul2026 asks for Kokkos 5" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps" KOKKOS_SOURCE="$work/kokkos" bash "$build"
expect_error "build_lammps_kokkos.sh unknown backend" "ETD_DPD_KOKKOS_BACKEND=hip" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps" KOKKOS_SOURCE="$work/kokkos" \
  ETD_DPD_KOKKOS_AS_5=1 ETD_DPD_KOKKOS_BACKEND=hip bash "$build"
expect_error "build_lammps_kokkos.sh KOKKOS_SOURCE no Kokkos tree" "no Kokkos source tree" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps" KOKKOS_SOURCE="$work/lammps" bash "$build"
expect_error "build_lammps_kokkos.sh KOKKOS_SOURCE no folder" "KOKKOS_SOURCE=$work/none is no folder" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps" KOKKOS_SOURCE="$work/none" bash "$build"
expect_error "build_lammps_kokkos.sh LAMMPS_SOURCE no LAMMPS tree" "no LAMMPS source tree .*no src/version.h" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/kokkos" KOKKOS_SOURCE="$work/kokkos" bash "$build"
# an installed Kokkos (ETD_DPD_KOKKOS_INSTALLED): a folder with its KokkosConfigVersion.cmake,
# for the openmp backend
expect_error "build_lammps_kokkos.sh ETD_DPD_KOKKOS_INSTALLED no folder" \
  "ETD_DPD_KOKKOS_INSTALLED=$work/none is no folder" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps" ETD_DPD_KOKKOS_INSTALLED="$work/none" bash "$build"
expect_error "build_lammps_kokkos.sh ETD_DPD_KOKKOS_INSTALLED no installed Kokkos" \
  "has no KokkosConfigVersion.cmake" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps" ETD_DPD_KOKKOS_INSTALLED="$work/kokkos" bash "$build"
mkdir -p "$work/installed"
printf 'set(PACKAGE_VERSION "5.2.2")\n' >"$work/installed/KokkosConfigVersion.cmake"
expect_error "build_lammps_kokkos.sh ETD_DPD_KOKKOS_INSTALLED with backend cuda" \
  "an installed Kokkos serves the openmp backend only" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps" ETD_DPD_KOKKOS_INSTALLED="$work/installed" \
  ETD_DPD_KOKKOS_BACKEND=cuda bash "$build"
printf 'set(PACKAGE_VERSION "unknown")\n' >"$work/installed/KokkosConfigVersion.cmake"
expect_error "build_lammps_kokkos.sh ETD_DPD_KOKKOS_INSTALLED without a version" \
  "no PACKAGE_VERSION in $work/installed/KokkosConfigVersion.cmake" \
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps" ETD_DPD_KOKKOS_INSTALLED="$work/installed" bash "$build"
[ ! -e "$work/cache" ] || { echo "FAIL: a stopped build left $work/cache behind"; failures=$((failures + 1)); }
[ "$failures" -eq 0 ] && echo PASS
exit "$failures"

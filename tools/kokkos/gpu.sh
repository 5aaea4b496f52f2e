#!/usr/bin/env bash
# The GPU leg of the KOKKOS styles in one command. On a machine with an NVIDIA GPU it
#   build  builds Kokkos (shared; CUDA, Kokkos_ARCH_HOPPER90, with OpenMP on the host) and a
#          KOKKOS LAMMPS against it (build_lammps_kokkos.sh with ETD_DPD_KOKKOS_BACKEND=cuda),
#          then the package with ETD_DPD_KOKKOS=ON (the plugin and the KOKKOS tests' programs);
#   pack   packs that build (the LAMMPS prefix without its build folders, and the plugin and test
#          programs with their CTest files) into SOURCES/prebuilt.tar.xz, so that a GPU machine
#          with the same CUDA driver generation runs it instead of building (nvcc takes about an
#          hour on two cores for this LAMMPS; a device lease is minutes);
#   test   runs the equivalence tests on the GPU (ctest -L kokkos: test_kokkos_styles on 1 and 2
#          ranks sharing the GPU, -k on g 1, and the solve's kernels against the CPU solve);
#   bench  measures atom-steps per second on the Groot-Warren fluid (bench/kokkos/
#          in.kokkos_throughput: n = 3, a = 25, gamma = 4.5, s = 2, rc = 1, kBT = 1, m = 0.01) at
#          each size, for the cases (--cases):
#            gen-nve       dpd/gen/kk + fix nve, dt 0.0007 (stock's largest step at m = 0.01)
#            dpd-nve       LAMMPS's dpd/kk + fix nve, the same dt
#            gen-nve-half  dpd/gen/kk + fix nve with -pk kokkos neigh half newton on
#            dpd-nve-half  dpd/kk + fix nve likewise (each style's fastest setting is compared too)
#            etd-implicit  fix etd/kk scheme implicit, dt 0.005 \  each at its largest
#            shardlow      fix shardlow/kk + nve, dt 0.004     /  seed-checked step
#            etd-diagonal  fix etd/kk scheme diagonal, dt 0.0005  (accuracy matrix, GW m = 0.01)
#            gen-nve-sort20  gen-nve with atom_modify sort 20 (on a GPU dpd/gen/kk takes LAMMPS's
#                          period, 1000 steps; on the host's threads it keeps sorting every 20)
#          All but the -half cases run at the package kokkos defaults of the device (neigh full,
#          newton off on a GPU). The implicit scheme and shardlow are compared in simulated time
#          x atoms per second (atom-steps/s x dt): equal accuracy, bench/accuracy/results/matrix.md.
# Results: RESULTS/gpu.jsonl (one line a run), RESULTS/gpu-tests.jsonl (the tests' count) and
# RESULTS/gpu.md (bench/kokkos/gpu_table.py); with $OUT set (the device tool's folder that comes
# back) they and logs.tar.gz are copied there after each step. RESULTS: bench/kokkos/results with
# cuda, ./build-gpu-results with openmp.
#
# Needs: nvcc 12.0 or newer with a host compiler it accepts (CUDA 13 with Kokkos 4.6: the source
# is patched, tools/kokkos/kokkos-4.6.1-cuda13.patch), CMake 3.16 or newer, MPI (mpicxx, mpirun).
# A machine without network takes the sources from tools/kokkos/pack_sources.sh, in
# ./build-gpu-sources (SOURCES, or ETD_DPD_GPU_SOURCES): Boost, Random123 and GoogleTest where it
# has none of its own, and Debian's Open MPI (openmpi.tar.xz, unpacked into / without replacing
# a file) where it has no MPI. With SOURCES/prebuilt.tar.xz (the pack phase, made on a machine
# with the same nvcc) the build is unpacked instead of made, and the phases run from the folder
# that packed it (a link to this checkout where the paths differ: CTest files are absolute); a
# packed LAMMPS that does not run there stops the command.
#
# Usage: tools/kokkos/gpu.sh [--phases build,test,bench] [--sizes 32000,256000,2048000]
#          [--steps 500] [--warmup 20] [--timeout 20] [--cases LIST] [--results DIR] [--until T]
#   --steps    timed steps per run; a run also stops after --timeout seconds of its loop (LAMMPS's
#              timer timeout, checked every step; the warm-up likewise) and the steps done are
#              counted
#   --phases   any of build, pack, test, bench (pack: after build, on the machine that built)
#   --until    a deadline, in seconds since the epoch (date +%s), by which the bench and test
#              phases end: a bench run that could not finish by then is skipped (a row says so)
#              and ctest is stopped there, the tests it did not finish counted as not run; so a
#              command with a wall-clock limit still brings its results back
# Environment: as build_lammps_kokkos.sh and test.sh. ETD_DPD_THREADS: the host's threads of
# every bench run (-k on g 1 t N; default all cores). ETD_DPD_KOKKOS_BACKEND=openmp (default
# cuda) runs the same phases on the OpenMP KOKKOS LAMMPS with ETD_DPD_THREADS threads (default
# 1): the script's check on a machine without a GPU. ETD_DPD_GPU_TEST_TIMEOUT: seconds per test
# (default 240).
#
# With the device tool: here, pack_sources.sh, then
#   ETD_DPD_KOKKOS_BACKEND=cuda tools/kokkos/gpu.sh --phases build,pack
# (tools/kokkos/rehearse_device.sh rehearses the call here), and on the GPU one call, the
# benchmark first (each run bounded by --timeout), then the tests (the packed files ride in
# carry; the tree itself is about 14 MiB):
#   run(command="u=$(( $(date +%s) + 520 ));
#                tools/kokkos/gpu.sh --phases bench --timeout 5 --warmup 10 --until $((u - 200));
#                ETD_DPD_GPU_TEST_TIMEOUT=150 tools/kokkos/gpu.sh --phases test --until $u",
#       timeout_s=540,
#       carry=["build-gpu-sources/kokkos.tar.xz", "build-gpu-sources/lammps.tar.xz",
#              "build-gpu-sources/deps.tar.xz", "build-gpu-sources/openmpi.tar.xz",
#              "build-gpu-sources/prebuilt.tar.xz", "build-gpu-sources/prebuilt.root"])
# Without prebuilt.tar.xz the same call builds there first (16 cores: most of a lease).
set -euo pipefail
args=("$@")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
log() { printf '[etd-dpd %s] %s\n' "$(date +%H:%M:%S)" "$*" >&2; }
die() { printf '[etd-dpd] ERROR: %s\n' "$*" >&2; exit 1; }

phases=build,test,bench
sizes=32000,256000,2048000
steps=500
warmup=20
timeout=20
# the bench's cases, in the order they run: case | pair | integrator | dt | package kokkos
# keywords (none: the device's defaults) | atom_modify sort period (none: LAMMPS's, 1000)
case_table=(
  "gen-nve|dpd/gen|nve|0.0007||" "dpd-nve|dpd|nve|0.0007||"
  "gen-nve-half|dpd/gen|nve|0.0007|neigh half newton on|" "dpd-nve-half|dpd|nve|0.0007|neigh half newton on|"
  "etd-implicit|dpd/gen|implicit|0.005||" "shardlow|dpd/fdt/energy|shardlow|0.004||"
  "etd-diagonal|dpd/gen|etd|0.0005||" "gen-nve-sort20|dpd/gen|nve|0.0007||20"
)
# a case's row of case_table (nothing for an unknown case)
case_row() { local row; for row in "${case_table[@]}"; do [ "${row%%|*}" != "$1" ] || echo "$row"; done; }
cases=$(for row in "${case_table[@]}"; do printf '%s,' "${row%%|*}"; done)
cases=${cases%,}
results=
until=
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    --phases|--sizes|--steps|--warmup|--timeout|--cases|--results|--until)
      [ $# -ge 2 ] || die "$1 needs a value (--help)" ;;
    *) die "unknown argument $1 (--help)" ;;
  esac
  case "$1" in
    --phases) phases=$2 ;; --sizes) sizes=$2 ;; --steps) steps=$2 ;; --warmup) warmup=$2 ;;
    --timeout) timeout=$2 ;; --cases) cases=$2 ;; --results) results=$2 ;; --until) until=$2 ;;
  esac
  shift 2
done
[ -z "$until" ] || [[ "$until" =~ ^[0-9]+$ ]] || die "--until $until: seconds since the epoch (date +%s)"
for size in ${sizes//,/ }; do [[ "$size" =~ ^[1-9][0-9]*$ ]] || die "--sizes: $size is no number of atoms"; done
[ -n "${sizes//,/}" ] || die "--sizes: no size given"
[[ "$steps" =~ ^[1-9][0-9]*$ ]] || die "--steps $steps: a positive number of steps"
[[ "$warmup" =~ ^[0-9]+$ ]] || die "--warmup $warmup: a number of steps"
[[ "$timeout" =~ ^[1-9][0-9]*$ ]] || die "--timeout $timeout: seconds, positive"
# seconds left before --until (a large number without one)
seconds_left() { if [ -n "$until" ]; then echo $((until - $(date +%s))); else echo 1000000000; fi; }
for phase in ${phases//,/ }; do
  case "$phase" in build|pack|test|bench) ;; *) die "unknown phase $phase (--help)" ;; esac
done
for case_name in ${cases//,/ }; do
  [ -n "$(case_row "$case_name")" ] || die "unknown case $case_name (--help)"
done
export ETD_DPD_KOKKOS_BACKEND=${ETD_DPD_KOKKOS_BACKEND:-cuda}
backend=$ETD_DPD_KOKKOS_BACKEND
has() { [[ ",$phases," == *",$1,"* ]]; }
sources=${ETD_DPD_GPU_SOURCES:-$root/build-gpu-sources}
build=$root/build-kokkos; [ "$backend" = cuda ] && build=$root/build-kokkos-cuda
build=${ETD_DPD_KOKKOS_BUILD:-$build}

# ---- a packed build: run from the folder that packed it ---------------------------------------
prebuilt=
if [ "$backend" = cuda ] && ! has pack && [ -f "$sources/prebuilt.tar.xz" ] && [ -f "$sources/prebuilt.root" ]; then
  packed_root=$(cat "$sources/prebuilt.root")
  if [ "$packed_root" != "$root" ]; then
    if [ ! -e "$packed_root" ]; then
      mkdir -p "$(dirname "$packed_root")" && ln -s "$root" "$packed_root"
      log "this checkout linked at $packed_root, where the packed build was made"
    elif [ "$(cd "$packed_root" && pwd -P)" != "$(cd "$root" && pwd -P)" ]; then
      die "the build in $sources/prebuilt.tar.xz was packed at $packed_root, which here is another folder"
    fi
    exec bash "$packed_root/tools/kokkos/gpu.sh" "${args[@]}"
  fi
  prebuilt=$sources/prebuilt.tar.xz
fi

if [ -z "$results" ]; then
  if [ "$backend" = cuda ]; then results=$root/bench/kokkos/results; else results=$root/build-gpu-results; fi
fi
logs=$root/build-gpu-results/logs
mkdir -p "$results" "$logs"
table() { python3 "$root/bench/kokkos/gpu_table.py" "$results/gpu.jsonl" "$results/gpu-tests.jsonl" >"$results/gpu.md"; }
copy_out() {  # results and logs to the device tool's folder (8 files at most), after each step:
  [ -n "${OUT:-}" ] || return 0  # a command stopped at its time limit keeps what is there
  cp "$results"/gpu*.jsonl "$results"/gpu.md "$OUT"/ 2>/dev/null || true
  tar -C "$logs" -czf "$OUT/logs.tar.gz" . 2>/dev/null || true
}
trap copy_out EXIT
untar_xz() {  # ARCHIVE DIR [keep]: tar -J where tar has xz, else Python's tarfile; keep: no file replaced
  local keep=${3:-}
  if command -v xz >/dev/null; then
    tar -C "$2" -xJf "$1" ${keep:+--skip-old-files}
  else
    python3 - "$1" "$2" "$keep" <<'PY'
import os, sys, tarfile
archive, dest, keep = sys.argv[1:4]
with tarfile.open(archive, "r:xz") as t:
    for m in t.getmembers():
        # names under dest, as tar does (openmpi.tar.xz holds absolute ones)
        m.name = m.name.lstrip("/")
        if m.islnk():
            m.linkname = m.linkname.lstrip("/")
        if keep and os.path.lexists(os.path.join(dest, m.name)) and not m.isdir():
            continue
        t.extract(m, dest, set_attrs=not m.isdir())
PY
  fi
}

# ---- what the machine has ----------------------------------------------------------------
command -v cmake >/dev/null || [ -n "$prebuilt" ] || die "no cmake"
install_openmpi() {  # Debian's Open MPI from pack_sources.sh, where the machine has none
  [ -f "$sources/openmpi.tar.xz" ] || die "no MPI (mpicxx and mpirun), and no $sources/openmpi.tar.xz"
  log "no MPI here: Debian's Open MPI from $sources/openmpi.tar.xz into / (no file replaced)"
  untar_xz "$sources/openmpi.tar.xz" / keep
  ldconfig 2>/dev/null || true
}
if ! command -v mpicxx >/dev/null || ! command -v mpirun >/dev/null; then install_openmpi; fi
log "MPI: $(mpirun --version 2>&1 | head -1)"
if [ "$backend" = cuda ]; then
  command -v nvcc >/dev/null || { [ -x /usr/local/cuda/bin/nvcc ] && export PATH=/usr/local/cuda/bin:$PATH; } \
    || [ -n "$prebuilt" ] || die "no nvcc: the CUDA toolkit, 12.0 or newer"
  if command -v nvcc >/dev/null; then
    cuda_version=$(nvcc --version | sed -n 's/.*release \([0-9]*\.[0-9]*\).*/\1/p')
    [ "${cuda_version%%.*}" -ge 12 ] \
      || die "nvcc $cuda_version: Kokkos 4.6 for Hopper (sm_90) needs CUDA 12.0 or newer (13.x is patched)"
    log "nvcc $cuda_version; host compiler $(c++ --version | head -1); $(cmake --version | head -1)"
  fi
  if has test || has bench; then
    nvidia-smi -L >&2 || die "no GPU (nvidia-smi -L failed): the test and bench phases need one"
    nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv >&2 || true
  fi
fi

# ---- the packed build, where it runs here ----------------------------------------------------
prefix=
if [ -n "$prebuilt" ]; then
  t0=$(date +%s)
  marker=$build/.prebuilt
  if [ ! -f "$marker" ] || [ ! -f "$(sed -n 's/^prebuilt_prefix=//p' "$marker")/.complete" ]; then
    untar_xz "$prebuilt" /
  fi
  [ -f "$marker" ] || die "$prebuilt holds no $marker"
  prefix=$(sed -n 's/^prebuilt_prefix=//p' "$marker")
  [ -f "$prefix/.complete" ] || die "$prebuilt holds no complete LAMMPS at $prefix"
  # the packed LAMMPS links Debian's libmpi.so.40; a machine whose own MPI is another one gets it
  if ldd "$prefix/bin/lmp" | grep -q 'not found'; then
    install_openmpi
  fi
  if ! "$prefix/bin/lmp" -h >"$logs/prebuilt-check.log" 2>&1; then
    ldd "$prefix/bin/lmp" >>"$logs/prebuilt-check.log" 2>&1 || true
    tail -20 "$logs/prebuilt-check.log" >&2
    # building here instead would take most of a device lease: say so, and let the caller choose
    die "the packed LAMMPS does not run here (above); without $prebuilt this command builds here"
  else
    log "packed build unpacked: LAMMPS at $prefix, package at $build ($(( $(date +%s) - t0 )) s)"
  fi
fi

if [ -z "$prebuilt" ]; then
  # ---- sources: the packed ones where none is named -----------------------------------------
  unpack() {  # NAME: $sources/NAME.tar.xz into $sources/unpacked, once
    [ -d "$sources/unpacked/$1" ] || { mkdir -p "$sources/unpacked" && untar_xz "$sources/$1.tar.xz" "$sources/unpacked"; }
  }
  if [ -z "${KOKKOS_SOURCE:-}" ]; then
    [ -f "$sources/kokkos.tar.xz" ] || die "set KOKKOS_SOURCE, or run tools/kokkos/pack_sources.sh first"
    unpack kokkos; export KOKKOS_SOURCE=$sources/unpacked/kokkos
  fi
  if [ -z "${LAMMPS_SOURCE:-}" ] && [ -z "${ETD_DPD_LAMMPS:-}" ] && [ -f "$sources/lammps.tar.xz" ]; then
    unpack lammps; export LAMMPS_SOURCE=$sources/unpacked/lammps
  fi
  compiles() { printf '%s\nint main() { return 0; }\n' "$1" | c++ -std=c++17 -x c++ - "${@:2}" -o /dev/null 2>/dev/null; }
  cmake_args=()
  if ! compiles '#include <boost/random/normal_distribution.hpp>' || ! compiles '#include <Random123/philox.h>'; then
    [ -f "$sources/deps.tar.xz" ] || die "no Boost or Random123 headers, and no $sources/deps.tar.xz"
    unpack deps; log "Boost and Random123 from $sources/unpacked/deps"
    cmake_args+=(-D "BOOST_RANDOM_INCLUDE_DIR=$sources/unpacked/deps/include"
                 -D "RANDOM123_INCLUDE_DIR=$sources/unpacked/deps/include")
  fi
  if ! compiles '#include <gtest/gtest.h>' -lgtest -pthread; then
    [ -f "$sources/deps.tar.xz" ] || die "no GoogleTest, and no $sources/deps.tar.xz"
    unpack deps
    gtest=$sources/unpacked/gtest
    if [ ! -f "$gtest/.complete" ]; then
      log "building GoogleTest into $gtest"
      { cmake -S "$sources/unpacked/deps/googletest" -B "$gtest/build" -D CMAKE_BUILD_TYPE=Release \
          -D BUILD_GMOCK=OFF -D CMAKE_INSTALL_PREFIX="$gtest" -D CMAKE_INSTALL_LIBDIR=lib \
        && cmake --build "$gtest/build" -j "${ETD_DPD_JOBS:-$(nproc)}" && cmake --install "$gtest/build"; } \
        >"$logs/gtest.log" 2>&1 || { tail -20 "$logs/gtest.log" >&2; die "GoogleTest build failed"; }
      touch "$gtest/.complete"
    fi
    cmake_args+=(-D "GTEST_ROOT=$gtest" -D "CMAKE_PREFIX_PATH=$gtest")
  fi
  export ETD_DPD_CMAKE_ARGS="${cmake_args[*]}"
  export ETD_DPD_BUILD_TARGETS="etddpd test_kokkos_styles test_friction_solve_kokkos"

  # ---- build --------------------------------------------------------------------------------
  t0=$(date +%s)
  prefix=$(bash "$root/tools/kokkos/build_lammps_kokkos.sh" 2>"$logs/lammps.log" | sed -n 's/^LAMMPS_KOKKOS_PREFIX=//p') \
    || { tail -40 "$logs/lammps.log" >&2; die "the KOKKOS LAMMPS did not build (logs in $logs)"; }
  [ -f "$prefix/.complete" ] || die "no complete KOKKOS LAMMPS at $prefix"
  log "KOKKOS LAMMPS ($backend): $prefix ($(( $(date +%s) - t0 )) s)"
  if has build || has test || has pack; then
    bash "$root/tools/kokkos/test.sh" -L kokkos -N >"$logs/build.log" 2>&1 \
      || { tail -40 "$logs/build.log" >&2; die "the package did not build (log: $logs/build.log)"; }
    log "package built in $build ($(( $(date +%s) - t0 )) s in all)"
    copy_out
  fi
fi

# ---- pack ---------------------------------------------------------------------------------
if has pack; then
  [ "$backend" = cuda ] || die "the pack phase is for the cuda backend"
  [ -f "$build/etddpdplugin.so" ] || die "no plugin at $build/etddpdplugin.so: the build phase first"
  printf 'prebuilt_prefix=%s\nprebuilt_root=%s\nnvcc=%s\n' "$prefix" "$root" "${cuda_version:-}" >"$build/.prebuilt"
  # the LAMMPS prefix without its build folders and the potential and benchmark files LAMMPS
  # installs (90 MB that no case reads), and the package's build without object files; absolute
  # names, unpacked at /
  tar -C / -cJf "$sources/prebuilt.tar.xz" \
    --exclude="${prefix#/}/build" --exclude="${prefix#/}/build-kokkos" --exclude="${prefix#/}/kokkos-source" \
    --exclude="${prefix#/}/share/lammps/potentials" --exclude="${prefix#/}/share/lammps/bench" \
    --exclude='CMakeFiles' --exclude='*.o' --exclude='*.log' \
    "${prefix#/}" "${build#/}"
  printf '%s\n' "$root" >"$sources/prebuilt.root"
  log "packed: $sources/prebuilt.tar.xz ($(du -m "$sources/prebuilt.tar.xz" | cut -f1) MiB), made at $root"
fi

# ---- test ---------------------------------------------------------------------------------
if has test; then
  status=0
  total=$(cd "$build" && ctest -N -L kokkos | sed -n 's/^Total Tests: *//p')
  stop=()    # ctest ends 10 s before --until
  [ -z "$until" ] || { left=$(( $(seconds_left) - 10 )); stop=(timeout --kill-after=5 "$(( left > 1 ? left : 1 ))"); }
  (cd "$build" && "${stop[@]}" ctest --output-on-failure -L kokkos --timeout "${ETD_DPD_GPU_TEST_TIMEOUT:-240}") \
    >"$logs/test.log" 2>&1 || status=$?
  grep -E "tests passed|Passed|Failed|\*\*\*" "$logs/test.log" >&2 || tail -20 "$logs/test.log" >&2
  # each test's result line (a ctest stopped at --until prints no summary)
  passed=$(grep -cE '^ *[0-9]+/[0-9]+ Test +#[0-9]+: .* Passed' "$logs/test.log" || true)
  ran=$(grep -cE '^ *[0-9]+/[0-9]+ Test +#[0-9]+: ' "$logs/test.log" || true)
  failed=$((ran - passed)) not_run=$((${total:-0} - ran))
  printf '{"kind": "tests", "backend": "%s", "label": "kokkos", "total": %d, "failed": %d, "not_run": %d, "exit": %d}\n' \
    "$backend" "${total:-0}" "$failed" "$not_run" "$status" >"$results/gpu-tests.jsonl"
  log "equivalence tests: $passed of ${total:-0} passed, $failed failed, $not_run not run"
  copy_out
fi

# ---- bench --------------------------------------------------------------------------------
if has bench; then
  plugin=$build/etddpdplugin.so
  [ -f "$plugin" ] || die "no plugin at $plugin: run the build phase first"
  if [ "$backend" = cuda ]; then
    # the host's threads run what stays on the host (the fix's search and atom loops, the pair
    # style's CPU loop under the implicit scheme): all the node's cores, for every case alike
    threads=${ETD_DPD_THREADS:-$(nproc)}
    kokkos=(-k on g 1 t "$threads" -sf kk)
    device="$(nvidia-smi --query-gpu=name --format=csv,noheader | head -1), $threads host threads"
  else
    threads=${ETD_DPD_THREADS:-1}
    kokkos=(-k on t "$threads" -sf kk)
    device="OpenMP, $threads of $(nproc) cores"  # nproc before OMP_NUM_THREADS, which it follows
  fi
  export OMP_PROC_BIND=false OMP_NUM_THREADS=$threads
  out=$results/gpu.jsonl
  : >"$out"
  lammps_version=$(sed -n 's/.*lammps-kokkos[a-z-]*-\([^-]*\)-.*/\1/p' <<<"$prefix")
  for natoms in ${sizes//,/ }; do
    for case_name in ${cases//,/ }; do
      row=$(case_row "$case_name")
      IFS='|' read -r _ pair integrator dt words sort <<<"$row"
      sort=${sort:-1000}
      package=(); [ -z "$words" ] || { read -r -a package <<<"-pk kokkos $words"; }
      runlog=$logs/bench-$case_name-$natoms.log
      # a run ends within twice its --timeout (warm-up and timed loop) plus its set-up; one that
      # could not end by --until is skipped (set-up alone takes tens of seconds at 2M atoms)
      limit=$((2 * timeout + 300)) left=$(seconds_left)
      if [ "$left" -lt $((2 * timeout + 60)) ]; then
        log "$case_name $natoms atoms: skipped, $left s left before --until"
        printf '{"kind": "run", "case": "%s", "natoms": %d, "error": "skipped: %d s left before --until"}\n' \
          "$case_name" "$natoms" "$left" >>"$out"
        table; copy_out
        continue
      fi
      [ "$left" -ge "$limit" ] || limit=$left
      t1=$(date +%s)
      status=0
      timeout "$limit" "$prefix/bin/lmp" -in "$root/bench/kokkos/in.kokkos_throughput" \
        -var plugin "$plugin" -var pair "$pair" -var integrator "$integrator" -var natoms "$natoms" \
        -var mass 0.01 -var dt "$dt" -var steps "$steps" -var warmup "$warmup" -var timeout "$timeout" -var timer_every 1 \
        -var sort "$sort" \
        "${kokkos[@]}" "${package[@]}" -log "$runlog" -screen none >"${runlog%.log}.out" 2>&1 || status=$?
      loop=$(awk '/^BENCH/{b=1} b&&/^Loop time/{print $4, $9; exit}' "$runlog")
      style=$(awk '/pair [a-z\/]+, perpetual/{print $3; exit}' "$runlog")
      if [ "$status" != 0 ] || [ -z "$loop" ]; then
        log "$case_name $natoms atoms: FAILED (exit $status; $runlog)"
        grep -h -m2 -E "ERROR|error" "$runlog" "${runlog%.log}.out" >&2 || true
        printf '{"kind": "run", "case": "%s", "natoms": %d, "error": "exit %d"}\n' "$case_name" "$natoms" "$status" >>"$out"
        table; copy_out
        continue
      fi
      read -r loop_s done_steps <<<"$loop"
      printf '{"kind": "run", "backend": "%s", "device": "%s", "case": "%s", "pair_style": "%s", "integrator": "%s", "natoms": %d, "mass": 0.01, "dt": %s, "steps": %d, "loop_s": %s, "timed_out": %s, "lammps": "%s", "kokkos": "%s", "sort": %d}\n' \
        "$backend" "$device" "$case_name" "${style%,}" "$integrator" "$natoms" "$dt" "$done_steps" "$loop_s" \
        "$([ "$done_steps" -lt "$steps" ] && echo true || echo false)" "$lammps_version" "${kokkos[*]} ${package[*]}" "$sort" >>"$out"
      log "$case_name $natoms atoms: $done_steps steps in $loop_s s ($(( $(date +%s) - t1 )) s with set-up)"
      table; copy_out
    done
  done
fi
if has test || has bench; then
  table
  cat "$results/gpu.md"
fi

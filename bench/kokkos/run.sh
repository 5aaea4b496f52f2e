#!/usr/bin/env bash
# Threads against ranks: dpd/gen/kk (Kokkos OpenMP) beside dpd/gen on MPI ranks and beside
# LAMMPS's dpd/kk and dpd, with fix nve, fix etd and fix etd scheme implicit on 24,000 atoms of
# the standard fluid; and the implicit scheme beside LAMMPS's fix shardlow and fix shardlow/kk at
# equal accuracy; all with the KOKKOS LAMMPS of tools/kokkos (one binary). The set-ups run
# alternated, ROUNDS times over, in one sitting; each run's loop time goes to
# results/throughput.jsonl (replaced; with ETD_DPD_BENCH_APPEND=1 this sitting's rounds are added
# after those there, with the same STEPS), and table.py turns it into results/throughput.md.
#   KOKKOS_SOURCE=... ETD_DPD_LAMMPS=trixie bash bench/kokkos/run.sh [ROUNDS [STEPS]]
# The machine should be otherwise idle.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
die() { echo "ERROR: run.sh: $*" >&2; exit 2; }
rounds=${1:-3}
steps=${2:-1000}
# the arguments and the plugin first, before the KOKKOS LAMMPS is looked up (or built)
[ $# -le 2 ] || die "usage: bash bench/kokkos/run.sh [ROUNDS [STEPS]]"
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || die "ROUNDS $rounds: a positive number of rounds"
[[ "$steps" =~ ^[1-9][0-9]*$ ]] || die "STEPS $steps: a positive number of steps"
build=${ETD_DPD_KOKKOS_BUILD:-$root/build-kokkos}
plugin="$build/etddpdplugin.so"
[ -f "$plugin" ] || die "no KOKKOS plugin at $plugin: run tools/kokkos/test.sh first"
prefix=$(bash "$root/tools/kokkos/build_lammps_kokkos.sh" | sed -n 's/^LAMMPS_KOKKOS_PREFIX=//p')
lmp="$prefix/bin/lmp"
mpi=(mpirun --oversubscribe); [ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
# threads bound one to a place, spread over them: LAMMPS's advice for KOKKOS with OpenMP
# (its manual, Speed_kokkos); every run records it
export OMP_PROC_BIND=spread OMP_PLACES=threads
# name | ranks | threads (0: no Kokkos) | pair style | integrator (nve; etd: fix etd diagonal;
# implicit: fix etd scheme implicit, and shardlow: LAMMPS's fix shardlow with dpd/fdt/energy, each
# at its largest step within tolerance for GW m = 0.01 in the accuracy matrix: 0.005 and 0.004)
# [| atom_modify sort period, LAMMPS's 1000 where not given: the /kk styles sort every 20 steps
# themselves, and the CPU style on ranks with that period is the ranks' best]
setups=(
  "dpd/gen, 2 ranks|2|0|dpd/gen|nve"
  "dpd/gen, 2 ranks, atom_modify sort 20|2|0|dpd/gen|nve|20"
  "dpd/gen/kk, 1 rank x 2 threads|1|2|dpd/gen|nve"
  "dpd/gen/kk, 2 ranks x 1 thread|2|1|dpd/gen|nve"
  "dpd/kk, 1 rank x 2 threads|1|2|dpd|nve"
  "dpd, 2 ranks|2|0|dpd|nve"
  "dpd/gen, 1 rank|1|0|dpd/gen|nve"
  "dpd/gen + fix etd, 2 ranks|2|0|dpd/gen|etd"
  "dpd/gen/kk + fix etd, 1 rank x 2 threads|1|2|dpd/gen|etd"
  "dpd/gen + fix etd implicit, 2 ranks|2|0|dpd/gen|implicit"
  "dpd/gen + fix etd implicit, 1 rank|1|0|dpd/gen|implicit"
  "dpd/gen/kk + fix etd/kk implicit, 1 rank x 2 threads|1|2|dpd/gen|implicit"
  "dpd/gen/kk + fix etd/kk implicit, 1 rank x 1 thread|1|1|dpd/gen|implicit"
  "fix shardlow, 2 ranks|2|0|dpd/fdt/energy|shardlow"
  "fix shardlow/kk, 1 rank x 2 threads|1|2|dpd/fdt/energy|shardlow"
)
mkdir -p "$here/results"
out="$here/results/throughput.jsonl"
first_round=1 sitting=1
if [ "${ETD_DPD_BENCH_APPEND:-0}" = 1 ] && [ -s "$out" ]; then
  read -r first_round sitting < <(/usr/bin/python3 -c '
import json, sys
runs = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]
print(max(r["round"] for r in runs) + 1, max(r.get("sitting", 1) for r in runs) + 1)' "$out")
else
  : >"$out"
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the two cores' cost of sharing data (sharing_probe.cpp), read just before each run on 2 or more
# threads: its two states on this kind of machine decide that run's speed
g++ -O2 -fopenmp "$here/sharing_probe.cpp" -o "$work/sharing_probe"
for round in $(seq "$first_round" $((first_round + rounds - 1))); do
  for setup in "${setups[@]}"; do
    IFS='|' read -r name ranks threads pair integrator sort <<<"$setup"
    sort=${sort:-1000}
    args=(-in "$here/in.kokkos_throughput" -var plugin "$plugin" -var pair "$pair" -var steps "$steps"
          -var integrator "$integrator" -var sort "$sort"
          -log "$work/log" -screen none)
    bind=()    # Open MPI binds each of 1 or 2 ranks to one core: threads would share it
    case "$integrator" in  # (nve and etd: the input's defaults for their masses)
      nve) dt=0.01 ;; etd) dt=0.002 ;; implicit) dt=0.005 ;; shardlow) dt=0.004 ;;
    esac
    args+=(-var dt "$dt")
    [ "$threads" != 0 ] && args+=(-k on t "$threads" -sf kk)
    [ "$threads" -gt 1 ] && bind=(--bind-to none)
    sharing=null
    [ "$threads" -gt 1 ] &&
      sharing=$(env -u OMP_PLACES OMP_PROC_BIND=false "$work/sharing_probe" |
                awk '/split differently +2 thread/{print $5}')
    "${mpi[@]}" "${bind[@]}" -np "$ranks" "$lmp" "${args[@]}"
    loop=$(awk '/^BENCH/{b=1} b&&/^Loop time/{print $4; exit}' "$work/log")
    # (the pair style's list: perpetual, or occasional where fix etd's own search feeds it)
    style=$(awk '/^BENCH/{b=1} /pair [a-z\/]+, (perpetual|occasional)/{s=$3} END{print s}' "$work/log")
    lammps=$(sed -n '1s/^LAMMPS (\(.*\))$/\1/p' "$work/log")
    printf '{"sitting": %d, "round": %d, "setup": "%s", "pair_style": "%s", "integrator": "%s", "ranks": %d, "threads": %d, "atoms": 24000, "steps": %d, "dt": %s, "loop_s": %s, "lammps": "%s", "cores": %d, "sharing_ms": %s, "omp_proc_bind": "%s", "omp_places": "%s", "sort": %d}\n' \
      "$sitting" "$round" "$name" "${style%,}" "$integrator" "$ranks" "$threads" "$steps" "$dt" "$loop" "$lammps" "$(nproc)" "$sharing" \
      "$OMP_PROC_BIND" "$OMP_PLACES" "$sort" | tee -a "$out"
  done
done
/usr/bin/python3 "$here/table.py" "$out" | tee "$here/results/throughput.md"

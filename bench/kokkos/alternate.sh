#!/usr/bin/env bash
# Builds of the plugin side by side on the fix etd set-ups of run.sh (in.kokkos_throughput,
# GW m = 0.01, 24,000 atoms; scheme implicit at dt = 0.005 by default): for each variant, fix
# etd/kk on 1 rank with 2 threads, and fix etd on 2 ranks, alternated round after round so that
# the machine's slow spells fall on all of them alike. Prints every run and then
# alternate_table.py's table: per variant and set-up, the median and the range, and each round's
# ratio (2 ranks / 2 threads of the same variant).
#   KOKKOS_SOURCE=... ETD_DPD_LAMMPS=trixie bash bench/kokkos/alternate.sh ROUNDS STEPS A.so B.so ...
# A variant PLUGIN.so@N runs with atom_modify sort N (the input's variable sort; default 1000).
# Environment:
#   ETD_DPD_BENCH_SCHEME  implicit (default; dt 0.005), diagonal (dt 0.002, run.sh's), or nve
#                         (dpd/gen/kk and dpd/gen with fix nve, m = 1, dt = 0.01)
#   ETD_DPD_BENCH_BIND=1  the threads bound as run.sh binds them (OMP_PROC_BIND=spread,
#                         OMP_PLACES=threads); default unbound, as the sittings before 2026-11-28
#   ETD_DPD_BENCH_OUT     a FILE.jsonl to which each round's runs are written (replaced), and
#                         alternate_table.py's table of them into FILE.md: a comparison's home
#                         when a document quotes it
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
die() { echo "ERROR: alternate.sh: $*" >&2; exit 2; }
# the arguments and settings first, before the KOKKOS LAMMPS is looked up (or built)
[ $# -ge 3 ] || die "usage: bash bench/kokkos/alternate.sh ROUNDS STEPS PLUGIN.so[@SORT] ..."
rounds=$1 steps=$2
shift 2
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || die "ROUNDS $rounds: a positive number of rounds"
[[ "$steps" =~ ^[1-9][0-9]*$ ]] || die "STEPS $steps: a positive number of steps"
for variant in "$@"; do
  [ -f "${variant%@*}" ] || die "no plugin at ${variant%@*}"
  [ "${variant%@*}" = "$variant" ] || [[ "${variant##*@}" =~ ^[0-9]+$ ]] ||
    die "$variant: @${variant##*@} is no atom_modify sort period"
done
case "${ETD_DPD_BENCH_SCHEME:-implicit}" in
  implicit) scheme=(-var integrator implicit -var dt 0.005) ;;
  diagonal) scheme=(-var integrator etd -var dt 0.002) ;;
  nve) scheme=(-var integrator nve) ;;
  *) die "ETD_DPD_BENCH_SCHEME=$ETD_DPD_BENCH_SCHEME: implicit, diagonal or nve" ;;
esac
out=${ETD_DPD_BENCH_OUT:-}
case "$out" in ''|*.jsonl) ;; *) die "ETD_DPD_BENCH_OUT=$out: a FILE.jsonl" ;; esac
prefix=$(bash "$root/tools/kokkos/build_lammps_kokkos.sh" | sed -n 's/^LAMMPS_KOKKOS_PREFIX=//p')
lmp="$prefix/bin/lmp"
mpi=(mpirun --oversubscribe); [ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
if [ "${ETD_DPD_BENCH_BIND:-0}" = 1 ]; then
  export OMP_PROC_BIND=spread OMP_PLACES=threads
else
  export OMP_PROC_BIND=false
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
runs=${out:-$work/runs.jsonl}
: >"$runs"
loop_time() { awk '/^BENCH/{b=1} b&&/^Loop time/{print $4; exit}' "$work/log"; }
# a variant's name: the plugin's full path, with @N where it sets atom_modify sort
variant_name() {
  local plugin=${1%@*} sort=
  [ "$plugin" = "$1" ] || sort=@${1##*@}
  echo "$(cd "$(dirname "$plugin")" && pwd)/$(basename "$plugin")$sort"
}
for round in $(seq "$rounds"); do
  for variant in "$@"; do
    name=$(variant_name "$variant")
    plugin=${name%@*} sort=1000
    [ "$plugin" = "$name" ] || sort=${name##*@}
    args=(-in "$here/in.kokkos_throughput" -var plugin "$plugin" -var pair dpd/gen -var steps "$steps"
          -var sort "$sort" "${scheme[@]}" -log "$work/log" -screen none)
    "${mpi[@]}" --bind-to none -np 1 "$lmp" "${args[@]}" -k on t 2 -sf kk
    threads=$(loop_time)
    "${mpi[@]}" -np 2 "$lmp" "${args[@]}"
    ranks=$(loop_time)
    echo "$round $name $threads $ranks" |
      awk '{printf "round %d %s: 2 threads %.3f s, 2 ranks %.3f s, ratio %.3f\n", $1, $2, $3, $4, $4 / $3}'
    printf '{"round": %d, "variant": "%s", "scheme": "%s", "steps": %d, "sort": %d, "omp_proc_bind": "%s", "threads_s": %s, "ranks_s": %s, "lammps": "%s", "cores": %d}\n' \
      "$round" "$name" "${ETD_DPD_BENCH_SCHEME:-implicit}" "$steps" "$sort" "$OMP_PROC_BIND" \
      "$threads" "$ranks" "$(sed -n '1s/^LAMMPS (\(.*\))$/\1/p' "$work/log")" "$(nproc)" >>"$runs"
  done
done
if [ -n "$out" ]; then
  /usr/bin/python3 "$here/alternate_table.py" "$out" | tee "${out%.jsonl}.md"
else
  /usr/bin/python3 "$here/alternate_table.py" "$runs"
fi

#!/usr/bin/env bash
# Loop time of one implicit-scheme configuration (validation/temperature/in.temperature_scan, m = 0.001,
# dt = 0.001, 400 timed steps after 100 of equilibration) for several builds of the plugin or
# newton settings, run alternately in rounds so that slow spells of a shared machine fall on
# all of them alike. Prints every round and each variant's minimum and median.
# Usage: bash bench/alternate.sh RANKS ROUNDS VARIANT ...
#   VARIANT = PLUGIN.so[:newton]   e.g. /tmp/old.so:on build/etddpdplugin.so:on build/etddpdplugin.so:off
# Environment: LMP (default: the lmp of tools/bootstrap.sh), INTEGRATOR (default "etd scheme
# implicit tol 1e-4 start velocity"), MASS (0.001), DT (0.001).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ $# -lt 3 ]; then
  echo "usage: bash bench/alternate.sh RANKS ROUNDS PLUGIN.so[:newton] ..." >&2
  exit 2
fi
ranks=$1 rounds=$2
shift 2
. "$here/tools/lammps_env.sh"
lmp=$LMP
integrator=${INTEGRATOR:-etd scheme implicit tol 1e-4 start velocity}
mass=${MASS:-0.001} dt=${DT:-0.001}
mpi=(mpirun -np "$ranks")
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for round in $(seq "$rounds"); do
  for variant in "$@"; do
    plugin=${variant%%:*} newton=on
    [[ $variant == *:* ]] && newton=${variant##*:}
    plugin=$(cd "$(dirname "$plugin")" && pwd)/$(basename "$plugin")
    (cd "$work" && "${mpi[@]}" "$lmp" -in "$here/validation/temperature/in.temperature_scan" -var plugin "$plugin" \
      -var mass "$mass" -var dt "$dt" -var integrator "$integrator" -var newton "$newton" \
      -var time "$(awk -v d="$dt" 'BEGIN{print 400*d}')" -var equil "$(awk -v d="$dt" 'BEGIN{print 100*d}')" \
      -log log.alternate -screen none >/dev/null)
    seconds=$(grep 'Loop time' "$work/log.alternate" | tail -1 | awk '{print $4}')
    echo "round $round $variant $seconds" | tee -a "$work/times"
  done
done
for variant in "$@"; do
  awk -v v="$variant" '$3 == v {print $4}' "$work/times" | sort -n |
    awk -v v="$variant" '{a[NR] = $1} END {printf "%s: n = %d, min %.3f s, median %.3f s\n", v, NR, a[1], (NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2)}'
done

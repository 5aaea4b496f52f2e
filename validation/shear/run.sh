#!/usr/bin/env bash
# Steady-shear viscosity eta = -P_xy / rate against the shear rate, for several integrators,
# several seeds per cell; one LAMMPS run (serial) per cell, 1.5 + 1.5 time units each.
# Appends one line per run to results/results.dat; a line already there is not run again, so a stopped
# run is continued by calling the script again. Then prints the table (python/shear_viscosity.py).
#   bash validation/shear/run.sh                     # about 22 minutes on one core
# Environment:
#   RATES   shear rates                          (default "0.5 1 2")
#   SEEDS   seeds, one run each per cell         (default "1001 1002 1003 1004")
#   CASES   integrator:dt pairs, integrator as in examples/shear/in.shear (default "stock:0.0005 nve:0.0005
#           diag:0.0005 implicit:0.003 implicit:0.001")
#   LMP     LAMMPS binary (default: from tools/bootstrap.sh, which also builds the plugin)
#   PLUGIN  the plugin (default build/etddpdplugin.so)
#   RESULTS results file (default validation/shear/results/results.dat)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/../.." && pwd)
. "$top/tools/lammps_env.sh"
plugin=$PLUGIN
rates=${RATES:-0.5 1 2}
seeds=${SEEDS:-1001 1002 1003 1004}
cases=${CASES:-stock:0.0005 nve:0.0005 diag:0.0005 implicit:0.003 implicit:0.001}
results=${RESULTS:-$here/results/results.dat}

mkdir -p "$here/logs" "$(dirname "$results")"
[ -s "$results" ] || echo "# integrator dt rate seed kBT eta slope   (eta = -<P_xy>/rate; kBT from temp/deform; slope = fitted dv_x/dy)" >"$results"
cd "$here"
for seed in $seeds; do
  for rate in $rates; do
    for spec in $cases; do
      integ=${spec%%:*} dt=${spec#*:}
      if awk -v i="$integ" -v d="$dt" -v r="$rate" -v s="$seed" \
           '$1 == i && $2 + 0 == d + 0 && $3 + 0 == r + 0 && $4 == s { found = 1 } END { exit !found }' "$results"; then
        continue
      fi
      log=logs/log.$integ.$dt.$rate.$seed
      start=$SECONDS
      "$LMP" -in "$top/examples/shear/in.shear" -var plugin "$plugin" -var integ "$integ" -var dt "$dt" \
        -var rate "$rate" -var seed "$seed" -log "$log" -screen none
      line=$(grep '^RESULT' "$log" | tail -1)
      [ -n "$line" ] || { echo "no RESULT in $log" >&2; exit 1; }
      # RESULT integ I dt DT rate R plane P seed S kT K eta E slope G
      set -- $line
      printf '%s %s %s %s %s %s %s\n' "$3" "$5" "$7" "${11}" "${13}" "${15}" "${17}" >>"$results"
      echo "$integ dt $dt rate $rate seed $seed: kBT ${13} eta ${15} slope ${17} ($((SECONDS - start)) s)"
    done
  done
done
tcaf=()    # the zero-shear eta_0 of run_tcaf.sh, where it has been run
[ -s "$here/results/tcaf/nve-0.0005_summary.txt" ] && tcaf=(--tcaf "$here/results/tcaf/nve-0.0005_summary.txt")
MPLBACKEND=Agg /usr/bin/python3 "$top/python/shear_viscosity.py" "$results" \
  --reference stock,nve --plot "$here/figures/eta_vs_rate.png" "${tcaf[@]}"

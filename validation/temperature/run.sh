#!/usr/bin/env bash
# Long physics validation (not part of CI): equilibrium kBT against time step for fix etd and the
# stock styles at m = 0.1, 0.01 and 0.001, at the time steps of Mai-Duy, Phan-Thien and Tran-Cong
# (2013), Tables 2-4, side by side with their values. Integrators: scheme diagonal order 1 with
# the piecewise and the exact noise, order 2, the stock pair dpd/ext + fix nve (velocity-Verlet),
# and scheme implicit (also at larger steps). Periodic 4,000-atom box (validation/temperature/in.temperature_scan:
# n = 4, a = 18.75, gamma = 4.5, sigma = 3, s = 1/2, kBT = 1); the paper used Couette flow between
# walls. Production time scales with the velocity relaxation time m/gamma; the error is the
# standard error of five block averages. About 20 minutes on one core; writes
# validation/temperature/README.md. Usage: bash validation/temperature/run.sh [time scale factor, default 1]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$here/tools/lammps_env.sh"
scale=${1:-1}
out="$here/out/validation"; mkdir -p "$out"; cd "$out"
results="$out/results.txt"; : >"$results"
run() {    # label pair integrator mass dt time
  local label=$1 pair=$2 integrator=$3 mass=$4 dt=$5 time
  time=$(awk "BEGIN { print $6 * $scale }")
  rm -f kbt_blocks.txt
  if "$LMP" -in "$here/validation/temperature/in.temperature_scan" -var plugin "$PLUGIN" \
      -var pair "$pair" -var integrator "$integrator" -var dt "$dt" -var mass "$mass" \
      -var time "$time" -var equil "$(awk "BEGIN { print $time / 4 }")" -log none -screen screen.txt \
      >/dev/null 2>&1 && grep -q "kBT=[0-9]" screen.txt; then
    local kT err
    kT=$(sed -n 's/.*kBT=\([0-9.]*\).*/\1/p' screen.txt | tail -1)
    err=$(awk '!/^#/ { n++; s += $2; q += $2 * $2 } END { m = s / n; printf "%.4f", sqrt((q / n - m * m) / (n - 1)) }' kbt_blocks.txt)
    echo "$mass|$dt|$label|$kT|$err" >>"$results"
  else
    echo "$mass|$dt|$label|fails|" >>"$results"
  fi
  tail -1 "$results"
}
scan() {    # mass time dt...
  local mass=$1 time=$2; shift 2
  for dt in "$@"; do
    run "etd" gen "etd" "$mass" "$dt" "$time"
    run "etd noise exact" gen "etd noise exact" "$mass" "$dt" "$time"
    run "etd order 2" gen "etd order 2" "$mass" "$dt" "$time"
    run "stock dpd/ext + nve" stock nve "$mass" "$dt" "$time"
    run "etd scheme implicit" gen "etd scheme implicit" "$mass" "$dt" "$time"
  done
}
scan 0.1 2.0 0.0009 0.001 0.003 0.005 0.007 0.009 0.01
scan 0.01 0.8 0.0001 0.0003 0.0005 0.0007 0.0009 0.001 0.003 0.005 0.007
for dt in 0.01; do run "etd scheme implicit" gen "etd scheme implicit" 0.01 "$dt" 0.8; done
scan 0.001 0.2 0.00003 0.00005 0.00007 0.0001 0.0002
for dt in 0.0005 0.001 0.003; do run "etd scheme implicit" gen "etd scheme implicit" 0.001 "$dt" 0.2; done
/usr/bin/python3 "$here/python/temperature_table.py" "$results" "$scale" >"$here/validation/temperature/README.md"
cat "$here/validation/temperature/README.md"

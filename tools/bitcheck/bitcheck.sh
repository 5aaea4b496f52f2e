#!/bin/bash
# Bit-for-bit trajectory check for changes that must not move behaviour (reorganisations).
#   bash tools/bitcheck/bitcheck.sh run DIR [CASE...]  # dumps of every case (or those named)
#                                                      # into DIR, from the current build
#   bash tools/bitcheck/bitcheck.sh compare A B  # lists the dumps of A and B that differ
# Cases: dpd/gen with nve, the implicit scheme (inertial, overdamped), the diagonal scheme and a
# hybrid/overlay; dpd/fpm with nve/sphere and both schemes; each on 1 and 2 ranks, newton
# on and off, straight through and across a restart at step 100. LMP and PLUGIN as in
# tools/lammps_env.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mode=${1:?run DIR or compare A B}
if [ "$mode" = compare ]; then
  bad=0
  for f in "$2"/*.dump; do
    g="$3/$(basename "$f")"
    if ! cmp -s "$f" "$g"; then echo "differs: $(basename "$f")"; bad=1; fi
  done
  [ $bad = 0 ] && echo "all $(ls "$2"/*.dump | wc -l) dumps identical"
  exit $bad
fi
out=$(mkdir -p "$2" && cd "$2" && pwd)
source "$here/../lammps_env.sh"
mpirun=(mpirun --allow-run-as-root --oversubscribe)
failed=0
# case: pair (system.lmp), mass, diameter (dpd/fpm), timestep, integrator
declare -A setup=(
  [gen_nve]="gen 0.05 - 0.002 nve"
  [gen_implicit]="gen 0.05 - 0.004 etd scheme implicit"
  [gen_overdamped]="gen 0.05 - 0.004 etd scheme implicit overdamped yes tol 1e-8"
  [gen_diagonal]="gen 0.05 - 0.004 etd scheme diagonal order 2 noise exact momentum conserve"
  [gen_hybrid]="hybrid 0.05 - 0.004 etd scheme implicit"
  [fpm_nve]="fpm 1.0 1.0 0.002 nve/sphere"
  [fpm_implicit]="fpm 0.05 0.5 0.004 etd scheme implicit"
  [fpm_diagonal]="fpm 0.5 1.0 0.004 etd scheme diagonal order 2 noise exact"
)
cases=(gen_nve gen_implicit gen_overdamped gen_diagonal gen_hybrid fpm_nve fpm_implicit fpm_diagonal)
[ $# -gt 2 ] && cases=("${@:3}")
for case in "${cases[@]}"; do
  [ -n "${setup[$case]:-}" ] || { echo "unknown case $case" >&2; exit 2; }
  read -r pair mass diameter dt fix <<<"${setup[$case]}"
  extra=""
  [ "$pair" = fpm ] && extra="omegax omegay omegaz"
  [ "$diameter" = - ] && diameter=1.0
  for np in 1 2; do for newton in on off; do for restart in 0 1; do
    name=$case.np$np.newton_$newton.restart$restart
    (cd "$out" && "${mpirun[@]}" -np $np "$LMP" -in "$here/in.bitcheck" -log $name.log -screen none \
       -var plugin "$PLUGIN" -var dir "$here" -var pair $pair -var mass $mass \
       -var diameter $diameter -var dt $dt -var fix "$fix" -var newton $newton \
       -var restart $restart -var out $name.dump -var extra "$extra") >/dev/null 2>&1 \
      && ! grep -q "^Open of file" "$out/$name.log" || { echo "FAILED: $name"; failed=1; }
  done; done; done
done
rm -f "$out"/*.restart
echo "dumps in $out"
exit $failed

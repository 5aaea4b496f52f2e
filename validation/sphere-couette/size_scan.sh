#!/bin/bash
# Size scan of examples/sphere-couette toward the paper's box (README "Size scan"): the paper's
# shape 40 x 30 x 30 scaled by s = 0.4, 0.5, 0.6 (16 x 12 x 12, 20 x 15 x 15, 24 x 18 x 18),
# three independent runs (seeds) per size, scheme diagonal (the paper's integrator), t = 3 of
# start-up and t = 12 of averaging each; then s = 0.8 with three seeds, two runs at a time. One folder per run in
# results/size_scan/, each with the drag and rdf files, the log and python/sphere_couette.py's
# table; the summary over sizes (python/sphere_couette_sizes.py) in results/size_scan/summary.txt.
# Run from anywhere: bash validation/sphere-couette/size_scan.sh [all | s0.8]
#   all (default): every run (about 3 CPU-hours); s0.8: only the second and third seeds at
#   s = 0.8 (about 55 CPU-minutes, 30 minutes on two cores); implicit: s = 0.6 with fix etd
#   scheme implicit, three seeds (about 30 CPU-minutes)
set -e
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$here/../..
source "$root/tools/lammps_env.sh"
out=$here/results/size_scan
mkdir -p "$out"
cp "$PLUGIN" "$out/scan_plugin.so"    # a private copy: rebuilds do not touch the running jobs
run() {    # s seed equil [scheme]
  local s=$1 seed=$2 scheme=${4:-diagonal} dir=$out/s$1_seed$2 wallbc=diffusive
  # (scheme implicit refuses fix wall/reflect/stochastic: specular walls and thermal layers)
  [ "$scheme" = diagonal ] || { dir=$out/s$1_${scheme}_seed$2; wallbc=layer; }
  local lx ly
  lx=$(awk -v s="$s" 'BEGIN { printf "%d", 40 * s }')
  ly=$(awk -v s="$s" 'BEGIN { printf "%d", 30 * s }')
  mkdir -p "$dir"
  (cd "$dir" && "$LMP" -in "$root/examples/sphere-couette/in.sphere-couette" -var plugin "$out/scan_plugin.so" \
     -var potdir "$root/potentials" -var Lx "$lx" -var Ly "$ly" -var H "$ly" -var seed "$seed" \
     -var equil "$3" -var steps 12000 -var scheme "$scheme" -var wallbc "$wallbc" -log log.lammps -screen none)
  /usr/bin/python3 "$root/python/sphere_couette.py" "$dir" > "$dir/table.txt"
  echo "s = $s seed $seed: $(grep 'drag F_x' "$dir/table.txt")"
}
what=${1:-all}
if [ "$what" = all ]; then
  for seed in 1 2 3; do
    for s in 0.4 0.5 0.6; do run $s $seed 3000; done
  done
  run 0.8 1 6000
fi
if [ "$what" = all ] || [ "$what" = s0.8 ]; then
  run 0.8 2 6000 & run 0.8 3 6000 & wait
fi
if [ "$what" = all ] || [ "$what" = implicit ]; then
  # the solvent at its set temperature (the diagonal scheme runs it at 0.230 instead of 0.25)
  run 0.6 1 3000 implicit & run 0.6 2 3000 implicit & wait
  run 0.6 3 3000 implicit
fi
rm -f "$out/scan_plugin.so"
# the mid-plane maps (up to 3 MB a run) are summarised in each table.txt and not kept
rm -f "$out"/s*_seed*/map.sphere-couette
# run names relative to results/size_scan, so the summary reads the same on any machine
(cd "$out" && /usr/bin/python3 "$root/python/sphere_couette_sizes.py" s[0-9].[0-9]_seed*) | tee "$out/summary.txt"
if ls -d "$out"/s0.6_implicit_seed* > /dev/null 2>&1; then
  (cd "$out" && /usr/bin/python3 "$root/python/sphere_couette_sizes.py" s0.6_implicit_seed*) | tee "$out/summary_implicit.txt"
fi

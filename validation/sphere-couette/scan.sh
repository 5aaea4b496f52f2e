#!/bin/bash
# Parameter scans of examples/sphere-couette (Mai-Duy, Phan-Thien and Khoo 2013, section 5):
#   sigma : colloid-solvent sigma 2.8 3.2 3.6 4.0 4.4 (Table 5)
#   a     : colloid-solvent a 1000 1250 1500 1750 2000 2250 (Table 6)
#   mass  : particle mass 0.005 0.01 0.02 0.05 0.1 (drag coefficient against Re, Figure 10)
# usage: validation/sphere-couette/scan.sh sigma|a|mass [OUTDIR] [extra lmp -var arguments]
# Runs one LAMMPS job per value in OUTDIR/<scan>_<value>/ (default size: the example's reduced
# box and length; pass e.g. "-var Lx 40 -var Ly 30 -var H 30 -var equil 60000 -var steps 90000
# -var block 10000" for the paper's) and prints one table row per run from python/sphere_couette.py.
# Environment: LMP (lmp binary), PLUGIN (etddpdplugin.so), RUN_PREFIX (default "nice -n 10").
set -e
scan=${1:?usage: scan.sh sigma|a|mass [OUTDIR] [extra -var args]}
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${2:-$root/out/sphere_couette_$scan}
shift $(( $# >= 2 ? 2 : 1 ))
LMP=${LMP:-lmp}
PLUGIN=${PLUGIN:-$root/build/etddpdplugin.so}
RUN_PREFIX=${RUN_PREFIX:-nice -n 10}
case $scan in
  sigma) var=colloid_sigma; values="2.8 3.2 3.6 4.0 4.4" ;;
  a)     var=colloid_a;     values="1000 1250 1500 1750 2000 2250" ;;
  mass)  var=mass;          values="0.005 0.01 0.02 0.05 0.1" ;;
  *) echo "unknown scan '$scan' (sigma, a or mass)" >&2; exit 1 ;;
esac
mkdir -p "$out"
for v in $values; do
  dir=$out/${scan}_$v
  mkdir -p "$dir"
  (cd "$dir" && $RUN_PREFIX "$LMP" -in "$root/examples/sphere-couette/in.sphere-couette" \
     -var plugin "$PLUGIN" -var potdir "$root/potentials" -var $var $v "$@" \
     -log log.lammps -screen none)
  mass=0.01; [ $scan = mass ] && mass=$v
  echo "== $var = $v"
  /usr/bin/python3 "$root/python/sphere_couette.py" "$dir" --mass $mass | tee "$dir/table.txt"
  # drag coefficient C_d = F / (0.5 pi a^2 rho m U^2) and Re = 2 a U rho m / eta (rho: number
  # density 4 times the mass), for Figure 10
  /usr/bin/python3 - "$dir/table.txt" $mass <<'PY'
import re, sys, math
text = open(sys.argv[1]).read(); m = float(sys.argv[2])
F = float(re.search(r"drag F_x\s+([-\d.]+)", text).group(1))
lo, hi = map(float, re.search(r"a_eff sphere \(eq 38\)\s+([\d.]+)-([\d.]+)", text).groups())
a, U, rho, eta = 0.5 * (lo + hi), 3.0, 4.0 * m, 3.9682
print(f"Re = {2 * a * U * rho / eta:.4f}  C_d = {F / (0.5 * math.pi * a * a * rho * U * U):.1f}"
      f"  Stokes C_d = 24/Re = {24 / (2 * a * U * rho / eta):.1f}")
PY
done

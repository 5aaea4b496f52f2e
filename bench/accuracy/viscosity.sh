#!/usr/bin/env bash
# The viscosity column of the accuracy matrix (results/viscosity.jsonl, README.md): reverse
# Poiseuille flow, 20 time units after 1 of equilibration, two seeds per cell; the reference is
# stock velocity-Verlet at a small step, the cells each integrator at the largest step the
# equilibrium observables allow (scan). Usage: bash bench/accuracy/viscosity.sh FLUID MASS
set -u
cd "$(dirname "$0")"
# LAMMPS (LMP) and the plugin (PLUGIN: the campaign's own copy unless set) for run.py
PLUGIN=${PLUGIN:-/tmp/accuracy/etddpdplugin.so}
. ../../tools/lammps_env.sh
export LMP PLUGIN
V="/usr/bin/python3 run.py viscosity"
fluid=${1:?usage: viscosity.sh GW|P|HS MASS} mass=${2:?usage: viscosity.sh FLUID MASS}
# reference, stock at its largest step, the implicit scheme (both settings) at theirs (scan)
case "$fluid:$mass" in
GW:0.01) cells="stock:0.0001 stock:0.0007 imp:0.007 impv:0.005" ;;
P:0.01) cells="stock:0.0001 stock:0.0003 imp:0.005 impv:0.004" ;;
*) echo "no cells for $fluid at mass $mass (README.md)" >&2; exit 2 ;;
esac
for seed in 0 1; do
  for cell in $cells; do
    $V --fluid "$fluid" --mass "$mass" --integrator "${cell%%:*}" --dt "${cell##*:}" --seed "$seed"
  done
done

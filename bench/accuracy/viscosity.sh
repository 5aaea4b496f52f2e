#!/usr/bin/env bash
# The viscosity column of the accuracy matrix (results/viscosity.jsonl, README.md): reverse
# Poiseuille flow, 20 time units after 1 of equilibration, two seeds per cell; the reference is
# stock velocity-Verlet at a small step, the cells each integrator at the largest step the
# equilibrium observables allow (scan). Usage: bash bench/accuracy/viscosity.sh FLUID MASS
set -u
cd "$(dirname "$0")"
V="/usr/bin/python3 run.py viscosity"
fluid=${1:?usage: viscosity.sh GW|P|HS MASS} mass=${2:?usage: viscosity.sh FLUID MASS}
case "$mass" in
0.01) cells="stock:0.0001 stock:0.0005 imp:0.005 impv:0.005" ;;
0.001) cells="stock:0.00003 stock:0.0001 imp:0.001 impv:0.001" ;;
*) echo "no cells for mass $mass" >&2; exit 2 ;;
esac
for seed in 0 1; do
  for cell in $cells; do
    $V --fluid "$fluid" --mass "$mass" --integrator "${cell%%:*}" --dt "${cell##*:}" --seed "$seed"
  done
done

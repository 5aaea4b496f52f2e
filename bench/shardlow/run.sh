#!/usr/bin/env bash
# The comparison with LAMMPS's fix shardlow (README.md): the runs behind the breakdown map and
# its table. Records go to bench/accuracy/results/ (the accuracy matrix's, through its run.py);
# map.md and map.png are regenerated from them. Usage:
#   bash bench/shardlow/run.sh [scan|viscosity|viscosity-m1|refusals|map ...]   (default: all
#   five, about 125 CPU-minutes; the GW fluid's own shardlow cells are in
#   bench/accuracy/campaign.sh GW and confirm.sh GW)
set -u
cd "$(dirname "$0")"
PLUGIN=${PLUGIN:-/tmp/accuracy/etddpdplugin.so}
. ../../tools/lammps_env.sh
export LMP PLUGIN
steps=${*:-scan viscosity viscosity-m1 refusals map}
run=(/usr/bin/python3 ../accuracy/run.py)
for step in $steps; do
  case "$step" in
    scan|viscosity|viscosity-m1|refusals|map) ;;
    *) echo "run.sh: unknown step '$step' (scan, viscosity, viscosity-m1, refusals or map)" >&2; exit 2 ;;
  esac
done
for step in $steps; do
  case "$step" in
  scan)
    # the gamma = 45 fluid at m = 0.01: per-pair friction stiffness gamma dt / m = 4500 dt;
    # the reference at 0.09, the stock cells up to 0.9
    [ -f /tmp/accuracy/HG.data ] || "${run[@]}" equilibrate --fluid HG
    S="${run[@]} scan --fluid HG --mass 0.01"
    $S --integrator stock --dt 0.00002 --role ref --windows 16
    $S --integrator shardlow --dt 0.0002 0.0005 0.001 0.002 0.005
    $S --integrator imp --dt 0.0005 0.001 0.002 0.003 0.005
    $S --integrator stock --dt 0.00005 0.0001 0.0002
    # the high-Sc target with s = 2 (S2: eta = 30, Sc = 500 at m = 1, gamma = 35.4, n = 5.29,
    # rc = 1.5): fix shardlow's best chance at that fluid, against the package's s < 2 design
    # (HS, the accuracy matrix) and stock; reference at Gamma dt / m = 0.026, then four seeds
    [ -f /tmp/accuracy/S2.data ] || "${run[@]}" equilibrate --fluid S2
    S="${run[@]} scan --fluid S2 --mass 1"
    $S --integrator stock --dt 0.0003 --role ref --windows 16
    $S --integrator shardlow --dt 0.005 0.01 0.02 0.03 0.04 0.06
    $S --integrator imp --dt 0.01 0.02 0.03 0.04 0.06 0.08 0.1 0.15
    $S --integrator stock --dt 0.0005 0.001 0.002 0.003
    "${run[@]}" confirm --fluid S2 --mass 1 --ref-dt 0.0003 --cell stock:0.002 stock:0.003 \
      shardlow:0.005 shardlow:0.01 imp:0.06 imp:0.08 imp:0.1 stock:0.001 ;;
  viscosity)
    # reverse Poiseuille flow, 10 time units after 1, seeds 10-15 (GW m = 0.01 at force 0.1:
    # each integrator at its largest step of the seed check) and 10-11 (HG)
    V="${run[@]} viscosity --time 10"
    for seed in 10 11 12 13 14 15; do
      for cell in shardlow:0.004 imp:0.005 stock:0.0007 shardlow:0.005 stock:0.0001; do
        $V --fluid GW --mass 0.01 --force 0.1 --integrator "${cell%%:*}" --dt "${cell##*:}" --seed "$seed"
      done
    done
    # GW at m = 0.1 and 0.001, four seeds: the reference, stock, shardlow and the implicit
    # scheme at their largest steps of the seed check (m = 1: viscosity-m1)
    for seed in 10 11 12 13; do
      for cells in "0.1 stock:0.0003 stock:0.005 shardlow:0.01 imp:0.02" \
                   "0.001 stock:0.00003 stock:0.0001 shardlow:0.0007 imp:0.001"; do
        set -- $cells
        mass=$1; shift
        for cell in "$@"; do
          $V --fluid GW --mass "$mass" --force 0.1 --integrator "${cell%%:*}" --dt "${cell##*:}" --seed "$seed"
        done
      done
    done
    for seed in 10 11; do
      for cell in stock:0.00005 shardlow:0.0005 shardlow:0.002 shardlow:0.005 imp:0.0005 imp:0.002 imp:0.005; do
        $V --fluid HG --mass 0.01 --force 0.3 --integrator "${cell%%:*}" --dt "${cell##*:}" --seed "$seed"
      done
    done ;;
  viscosity-m1)
    # GW at m = 1, the same cells: the flow's slowest mode relaxes in rho / (eta k^2) = 8.7 time
    # units there (0.1 at m = 0.01), so 40 time units of start-up and 40 of averaging, sixteen
    # seeds (about 35 CPU-minutes)
    for seed in $(seq 20 35); do
      for cell in stock:0.001 stock:0.005 shardlow:0.02 imp:0.04; do
        "${run[@]}" viscosity --equil 40 --time 40 --fluid GW --mass 1 --force 0.1 \
          --integrator "${cell%%:*}" --dt "${cell##*:}" --seed "$seed"
      done
    done ;;
  refusals) bash refusals.sh ;;
  map) /usr/bin/python3 map.py --figure map.png >map.md ;;
  esac
done

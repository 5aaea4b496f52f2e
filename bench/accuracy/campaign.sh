#!/usr/bin/env bash
# The scans behind results/scan.jsonl (README.md). One line per cell: its dt list; "ref" runs are
# stock velocity-Verlet at a small step with 16 windows; GW also scans LAMMPS's fix shardlow
# (dpd/fdt is s = 2 only). Usage:
#   bash bench/accuracy/campaign.sh FLUID [MASS ...]     FLUID = GW, P or HS; masses 1 0.1 0.01 0.001
# (each fluid's lines are independent: run two fluids side by side on two cores).
set -u
cd "$(dirname "$0")"
# LAMMPS (LMP) and the plugin (PLUGIN: the campaign's own copy unless set) for run.py
PLUGIN=${PLUGIN:-/tmp/accuracy/etddpdplugin.so}
. ../../tools/lammps_env.sh
export LMP PLUGIN
R="/usr/bin/python3 run.py scan"
fluid=${1:?usage: campaign.sh GW|P|HS [MASS ...]}
shift
masses=${*:-1 0.1 0.01 0.001}
for m in $masses; do
  case "$fluid:$m" in
  # the high-Sc fluid's friction rate Gamma/m is 35 times GW's (Gamma = 66.7 against 1.9): its
  # steps scale down by that, and a reference at Gamma dt / m = 0.03 below m = 0.1 would take
  # 10^6 steps of a 4,000-atom rc = 1.5 fluid (README.md)
  HS:1)
    $R --fluid HS --mass 1 --integrator stock --dt 0.0005 --role ref --windows 16
    $R --fluid HS --mass 1 --integrator stock --dt 0.0007 0.001 0.002 0.003 0.005
    $R --fluid HS --mass 1 --integrator diag --dt 0.002 0.005 0.01 0.02
    $R --fluid HS --mass 1 --integrator imp --dt 0.003 0.005 0.01 0.02 0.03 0.04 ;;
  HS:0.1)
    $R --fluid HS --mass 0.1 --integrator stock --dt 0.00005 --role ref --windows 16
    $R --fluid HS --mass 0.1 --integrator stock --dt 0.0001 0.0002 0.0003 0.0005 0.0007 0.001
    $R --fluid HS --mass 0.1 --integrator diag --dt 0.0002 0.0005 0.001 0.002
    $R --fluid HS --mass 0.1 --integrator imp --dt 0.001 0.002 0.004 0.007 0.01 0.015 0.02
    $R --fluid HS --mass 0.1 --integrator impv --dt 0.004 0.01 0.02 ;;
  HS:0.01)
    # velocity-Verlet with dpd/gen's forces (the same as dpd/ext's to round-off; a third of its
    # cost) for the reference and the stock scan: at Gamma dt / m = 0.1 the reference is 280,000
    # steps; stock at 0.00003 (0.2) checks it. Timings (timing.sh) run dpd/ext.
    $R --fluid HS --mass 0.01 --integrator stock --pair gen --dt 0.000015 --role ref --windows 16
    $R --fluid HS --mass 0.01 --integrator stock --pair gen --dt 0.00003 0.00005 0.00007 0.0001
    $R --fluid HS --mass 0.01 --integrator imp --dt 0.001 0.002 0.003 0.004 0.005 0.007 0.01
    $R --fluid HS --mass 0.01 --integrator impv --dt 0.002 0.003 0.004 0.005 0.007 0.01 ;;
  HS:0.001)
    # velocity-Verlet at Gamma dt / m = 0.1 would be 2.9 million steps: the reference is derived
    # (run.py derive-ref): kBT, P and g(r) of the m = 0.01 reference (the Boltzmann distribution
    # does not depend on the mass), D from D0 - c m fitted to the references at 1, 0.1 and 0.01
    # (residuals 0.01 %). Stock is not scanned (README.md: its step is bounded by the stiffness).
    /usr/bin/python3 run.py derive-ref --fluid HS --mass 0.001 --static-from 0.01 --d-from 1 0.1 0.01 \
      --seeds-from 0.1    # (and the seed check's, from m = 0.1's seeds; confirm.sh HS ... 0.001)
    # (from 0.003 on the fix stops with its missing-pair ERROR: at this mass the thermal speed,
    # 55, moves atoms 0.15 on average in a half drift at 0.005, beyond the skin 0.3)
    $R --fluid HS --mass 0.001 --integrator imp --dt 0.001 0.002 0.003
    $R --fluid HS --mass 0.001 --integrator impv --dt 0.002 0.003 ;;
  HS:*) echo "HS: mass $m not in the matrix" ;;
  *:1)
    $R --fluid "$fluid" --mass 1 --integrator stock --dt 0.001 --role ref --windows 16
    $R --fluid "$fluid" --mass 1 --integrator stock --dt 0.002 0.003 0.005 0.01 0.02 0.03 0.04
    $R --fluid "$fluid" --mass 1 --integrator diag --dt 0.003 0.005 0.01 0.02 0.03 0.04
    $R --fluid "$fluid" --mass 1 --integrator imp --dt 0.01 0.02 0.03 0.04 0.06 0.08
    [ "$fluid" != GW ] || $R --fluid GW --mass 1 --integrator shardlow --dt 0.01 0.02 0.03 0.04 0.06 0.08 ;;
  *:0.1)
    $R --fluid "$fluid" --mass 0.1 --integrator stock --dt 0.0003 --role ref --windows 16
    $R --fluid "$fluid" --mass 0.1 --integrator stock --dt 0.001 0.0015 0.002 0.003 0.005 0.007 0.01
    $R --fluid "$fluid" --mass 0.1 --integrator diag --dt 0.001 0.002 0.003 0.005 0.007 0.01
    $R --fluid "$fluid" --mass 0.1 --integrator imp --dt 0.005 0.007 0.01 0.015 0.02 0.03 0.04
    [ "$fluid" != GW ] || $R --fluid GW --mass 0.1 --integrator shardlow --dt 0.003 0.005 0.007 0.01 0.015 0.02 0.03 ;;
  *:0.01)
    $R --fluid "$fluid" --mass 0.01 --integrator stock --dt 0.0001 --role ref --windows 16
    $R --fluid "$fluid" --mass 0.01 --integrator stock --dt 0.00015 0.0002 0.0003 0.0005 0.0007 0.001
    $R --fluid "$fluid" --mass 0.01 --integrator diag --dt 0.0002 0.0003 0.0005 0.001 0.002 0.003
    $R --fluid "$fluid" --mass 0.01 --integrator imp --dt 0.002 0.003 0.004 0.005 0.007 0.01
    $R --fluid "$fluid" --mass 0.01 --integrator impv --dt 0.003 0.004 0.005 0.007
    [ "$fluid" != GW ] || $R --fluid GW --mass 0.01 --integrator shardlow --dt 0.002 0.003 0.004 0.005 0.007 0.01 ;;
  *:0.001)
    # P: Gamma dt / m = 0.17 at 0.000015 (0.34 at 0.00003 left the pressure 0.5 % high)
    if [ "$fluid" = P ]; then
      $R --fluid P --mass 0.001 --integrator stock --dt 0.000015 --role ref --windows 8
    else
      $R --fluid "$fluid" --mass 0.001 --integrator stock --dt 0.00003 --role ref --windows 16
    fi
    $R --fluid "$fluid" --mass 0.001 --integrator stock --dt 0.00005 0.00007 0.0001 0.00015 0.0002 0.0003
    $R --fluid "$fluid" --mass 0.001 --integrator diag --dt 0.00005 0.00007 0.0001 0.0002 0.0003 0.0005
    $R --fluid "$fluid" --mass 0.001 --integrator imp --dt 0.0005 0.0007 0.001 0.0015 0.002
    $R --fluid "$fluid" --mass 0.001 --integrator impv --dt 0.0007 0.001 0.0015 0.002
    [ "$fluid" != GW ] || $R --fluid GW --mass 0.001 --integrator shardlow --dt 0.0003 0.0005 0.0007 0.001 0.0015 ;;
  esac
done

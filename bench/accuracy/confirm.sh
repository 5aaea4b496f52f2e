#!/usr/bin/env bash
# The seed check behind results/confirm.jsonl (README.md, "The largest steps again with
# independent seeds"): the reference and each largest step of the GW and P scans at m = 0.01 and
# 0.001 once per seed (11-14, 16 windows each), and the next smaller steps where the seeds
# rejected one. The tables (python/accuracy_matrix.py) then take a largest step only where the
# mean over the seeds is within tolerance. Usage:
#   bash bench/accuracy/confirm.sh GW|P [SEEDS]     (SEEDS default "11 12 13 14"; split them
#                                                    over two cores, e.g. "11 12" and "13 14")
# About 25 CPU-minutes for GW, 90 for P (its m = 0.001 reference: 140,000 steps per seed).
set -u
cd "$(dirname "$0")"
PLUGIN=${PLUGIN:-/tmp/accuracy/etddpdplugin.so}
. ../../tools/lammps_env.sh
export LMP PLUGIN
fluid=${1:?usage: confirm.sh GW|P [SEEDS]}
seeds=${2:-11 12 13 14}
C="/usr/bin/python3 run.py confirm --seeds $seeds"
scan() {    # mass integrator dt: one cell once per seed, no reference
  for seed in $seeds; do
    /usr/bin/python3 run.py scan --fluid "$fluid" --mass "$1" --integrator "$2" --dt "$3" --windows 16 \
      --seed "$seed" --out confirm.jsonl
  done
}
case "$fluid" in
  GW)
    $C --fluid GW --mass 0.01 --ref-dt 0.0001 --cell stock:0.0007 imp:0.005 imp:0.007 impv:0.005
    $C --fluid GW --mass 0.001 --ref-dt 0.00003 --cell imp:0.001 impv:0.0015 stock:0.0001
    scan 0.001 impv 0.001 ;;
  P)
    $C --fluid P --mass 0.01 --ref-dt 0.0001 --cell stock:0.0003 imp:0.005 impv:0.007
    scan 0.01 impv 0.005
    scan 0.01 impv 0.004
    $C --fluid P --mass 0.001 --ref-dt 0.00003 --cell imp:0.0015 impv:0.002
    scan 0.001 imp 0.001
    scan 0.001 impv 0.0015 ;;
  *) echo "confirm.sh: fluid must be GW or P, got '$fluid'" >&2; exit 2 ;;
esac

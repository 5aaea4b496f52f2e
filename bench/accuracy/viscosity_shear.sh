#!/usr/bin/env bash
# The viscosity column of the accuracy matrix on the Groot-Warren fluid (n = 3, a = 25,
# gamma = 4.5, s = 2, kBT = 1) by homogeneous shear (examples/shear/in.shear: Lees-Edwards
# boundaries through fix deform ... remap v, eta = -<P_xy> / rate at rate 2, 0.5 time units of
# start-up and 4 of averaging, 3,000 atoms): stock pair dpd + nve at the matrix's reference step
# and at its largest step, fix etd scheme implicit at its largest steps (default, and tol 1e-4
# start velocity), four seeds each. Reverse Poiseuille flow (viscosity.sh) does not resolve 2 %
# on this fluid in 20 time units; this does.
#   m = 0.01 (default): reference 0.0001, stock 0.0007, implicit 0.007 / 0.005, and the default
#   implicit scheme at 0.005 (cell imp0.005); about 12 minutes
#   m = 0.001: reference 0.00003, stock 0.0001, implicit 0.001 / 0.0015 and the options at 0.001
#   (cell impv0.001); about 35 minutes
# Writes results/viscosity_shear/log.<cell>.<seed> (m = 0.001: log.m0.001.<cell>.<seed>; not
# kept in the repository), prints the RESULT lines and merges them into the summary
# results/viscosity_shear.jsonl (shear_table.py --dir), which the tables are made from. SEEDS (default "1 2 3 4") selects seeds, to split the work; RATE
# (default 2) the shear rate (logs then log.[m0.001.]rate<RATE>.<cell>.<seed>); CELLS (default
# all) the cells to run, e.g. CELLS="impv0.001"; SKIN (default 0.3) the neighbor skin; TPROD
# (default 4) the time units averaged (logs then log.[m...]tprod<TPROD>.<cell>.<seed>).
#   m = 1 and 0.1, the P fluid (n = 4, a = 18.75, s = 1/2, stock dpd/ext) at m = 1, 0.1, 0.01
#   and 0.001, and the HS fluid (dpd/design eta 30 sc 500 density 4 cutoff 1.5: a = 3.5328,
#   gamma = 6.971, s = 0.4244, rc = 1.5, stock dpd/ext) at m = 1 and 0.1: the reference, stock
#   and the implicit scheme at the matrix's steps (logs log.[P.|HS.]m<mass>.*). Where the
#   reference is costly (P m = 1, 0.01 and 0.001, HS) it is velocity-Verlet with dpd/gen's
#   forces (in.shear's integ nve: the same forces and the same integrator as stock, another
#   noise stream), as the matrix's HS references are.
#   HS at m = 0.01 and 0.001: velocity-Verlet is out of reach (300,000 and 3 million steps a
#   run), so only the implicit scheme runs, at its largest step and at a smaller one; its
#   reference is the m = 0.1 set's (shear_table.py --ref-from; README.md, "Viscosity").
# Usage: bash bench/accuracy/viscosity_shear.sh [0.01|0.001|1|0.1] [GW|P|HS]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
mass=${1:-0.01}
which=${2:-GW}
# steps: reference, stock, implicit, implicit with the options ("-": not in the matrix);
# extras: further cells, name:dt (stock* velocity-Verlet, ref* the reference's integrator at
# another step, impv* the implicit scheme with the options, others the default implicit
# scheme, diag* the diagonal scheme, e.g. "ref0.0000075:0.0000075"): the diagonal scheme at its
# largest step where the matrix has one; P m = 0.001 the implicit scheme at 0.001 and 0.0005;
# GW m = 1 stock and the diagonal scheme at 0.003 and the implicit scheme at 0.04, 0.03 and 0.02
# (its viscosity from the stress grows with its step), GW m = 0.1 the implicit scheme at 0.015,
# 0.01, 0.0075 and 0.005 and the reference's integrator at 0.0001 (its
# convergence), P m = 1 the implicit scheme at 0.06 and 0.04 (+3.2 % at 0.08); m = 0.01 the
# default at the step the seed check confirms; m = 0.001 the options at the default's step (at
# 0.0015 their viscosity is 3-4 % high); P m = 0.1 at 0.015 and 0.01 (at 0.02 its viscosity is
# 2.8 % high); P m = 0.01 the implicit scheme at 0.004 and 0.003, the options at 0.003 and at
# their equilibrium step 0.005 (at 0.005 / 0.004 the default's viscosity is 2.7 / 1.0 % high); P m = 0.001 the options at 0.0015 (+3.3 %
# at 0.002); HS m = 0.01 and 0.001 the implicit scheme at a step 3.5 and 2 times smaller (its
# convergence)
extras=""
ref_integ=stock
case "$which:$mass" in
  GW:0.01) prefix=""; steps=(0.0001 0.0007 0.007 0.005); extras="imp0.005:0.005 diag0.0005:0.0005" ;;
  GW:0.001) prefix="m0.001."; steps=(0.00003 0.0001 0.001 0.0015)
    extras="impv0.001:0.001 diag0.0001:0.0001" ;;
  GW:1) prefix="m1."; steps=(0.001 0.005 0.06 -)
    extras="stock0.003:0.003 imp0.04:0.04 imp0.03:0.03 imp0.02:0.02 diag0.005:0.005 diag0.003:0.003" ;;
  GW:0.1) prefix="m0.1."; steps=(0.0003 0.005 0.02 -)
    extras="diag0.003:0.003 imp0.015:0.015 imp0.01:0.01 imp0.0075:0.0075 imp0.005:0.005 ref0.0001:0.0001" ;;
  P:1) prefix="P.m1."; steps=(0.001 0.003 0.08 -); extras="imp0.06:0.06 imp0.04:0.04"; ref_integ=nve ;;
  P:0.1) prefix="P.m0.1."; steps=(0.0003 0.002 0.02 -); extras="imp0.015:0.015 imp0.01:0.01 diag0.003:0.003" ;;
  P:0.01) prefix="P.m0.01."; steps=(0.0001 0.0003 0.005 0.004)
    extras="diag0.0003:0.0003 imp0.004:0.004 imp0.003:0.003 impv0.003:0.003 impv0.005:0.005"; ref_integ=nve ;;
  P:0.001) prefix="P.m0.001."; steps=(0.000015 0.00003 0.0015 0.002)
    extras="imp0.001:0.001 imp0.0005:0.0005 impv0.0015:0.0015"
    ref_integ=nve ;;
  HS:1) prefix="HS.m1."; steps=(0.0005 0.0007 0.02 -); ref_integ=nve ;;
  HS:0.1) prefix="HS.m0.1."; steps=(0.00005 0.0005 0.02 0.02); ref_integ=nve ;;
  HS:0.01) prefix="HS.m0.01."; steps=(- - 0.007 0.007); extras="imp0.002:0.002" ;;
  HS:0.001) prefix="HS.m0.001."; steps=(- - 0.002 0.002); extras="imp0.001:0.001" ;;
  *) echo "viscosity_shear.sh: fluid and mass must be GW 0.01, 0.001, 1 or 0.1, P 1, 0.1, 0.01 or" \
          "0.001, or HS 1, 0.1, 0.01 or 0.001; got $which $mass" >&2; exit 2 ;;
esac
. "$root/tools/lammps_env.sh"
out="$here/results/viscosity_shear"
mkdir -p "$out"
cd "$out"
case "$which" in    # in.shear's stock style: dpd at s = 2, dpd/ext otherwise
  GW) fluid=(-var n 3 -var a 25 -var s 2 -var gamma 4.5) ;;
  P) fluid=(-var n 4 -var a 18.75 -var s 0.5 -var gamma 4.5) ;;
  HS) fluid=(-var n 4 -var a 3.5328 -var s 0.424428900898052 -var gamma 6.97099466424446
             -var rc 1.5) ;;
esac
fluid+=(-var kT 1.0 -var mass "$mass" -var tstart 0.5 -var tprod "${TPROD:-4}" -var skin "${SKIN:-0.3}")
# (at m = 1 and 0.1 the implicit scheme's steps with the streaming velocity, up to rate x L / 2
# = 10, move atoms 0.2-0.6 per step: the fix stops with its missing-pair ERROR at skin 0.3;
# SKIN=1.0 for m = 0.1; at m = 1, rate 2 heats velocity-Verlet's fluid to kBT 1.6)
rate=${RATE:-2}
fluid+=(-var rate "$rate")
[ "$rate" = 2 ] || prefix="${prefix}rate$rate."
[ "${TPROD:-4}" = 4 ] || prefix="${prefix}tprod$TPROD."
run() {    # cell integ dt fixopts seed ("-" for dt: a cell this set does not run)
  case " ${CELLS:-$1} " in *" $1 "*) ;; *) return 0 ;; esac
  [ "$3" != - ] || return 0
  local log="log.$prefix$1.$5"
  "$LMP" -in "$root/examples/shear/in.shear" -var plugin "$PLUGIN" "${fluid[@]}" -var integ "$2" \
    -var dt "$3" -var fixopts "$4" -var seed "$5" -log "$log" -screen none
  echo "$1 $(grep '^RESULT' "$log")"
}
for seed in ${SEEDS:-1 2 3 4}; do
  run ref "$ref_integ" "${steps[0]}" "" $seed
  run stock stock "${steps[1]}" "" $seed
  run imp implicit "${steps[2]}" "" $seed
  run impv implicit "${steps[3]}" "tol 1e-4 start velocity" $seed
  for extra in $extras; do
    integ=implicit opts=""
    case "$extra" in impv*) opts="tol 1e-4 start velocity" ;; stock*) integ=stock ;;
                     diag*) integ=diag ;; ref*) integ=$ref_integ ;; esac
    run "${extra%%:*}" "$integ" "${extra#*:}" "$opts" $seed
  done
done
/usr/bin/python3 "$here/shear_table.py" --dir "$out" > /dev/null    # the summary
# the tables of every set, written into results/viscosity_shear.md (README.md, "Viscosity")
/usr/bin/python3 "$here/shear_table.py" --ref-from HS.m0.01.rate0.2.=HS.m0.1.rate0.2. \
  --ref-from HS.m0.001.rate0.2.=HS.m0.1.rate0.2. --ref-from HS.m0.001.rate1.=HS.m0.1.rate0.2. \
  > "$here/results/viscosity_shear.md"

#!/usr/bin/env bash
# Cost per time unit of every integrator of the scans at its largest step (results/timing.jsonl):
# alternated rounds of 400 steps from the equilibrated configuration, on 1 and then 2 ranks.
# Run on an otherwise quiet machine. Usage: bash bench/accuracy/timing.sh [run.py time-matrix options]
set -u
cd "$(dirname "$0")"
# LAMMPS (LMP) and the plugin (PLUGIN: the campaign's own copy unless set) for run.py
PLUGIN=${PLUGIN:-/tmp/accuracy/etddpdplugin.so}
. ../../tools/lammps_env.sh
export LMP PLUGIN
# one sitting for every round, so that the tables compare them (run.py --sitting)
S=$(date +%H%M)
/usr/bin/python3 run.py time-matrix --ranks 1 --sitting "$S" "$@"
/usr/bin/python3 run.py time-matrix --ranks 2 --sitting "$S" "$@"
# each side at its own best neighbor skin against fix shardlow (bench/shardlow/map.md)
for r in 1 2; do
  /usr/bin/python3 run.py time --sitting "$S" --skin 0.7 --ranks $r --fluid GW --mass 0.01 --cell shardlow:0.004 imp:0.005
  /usr/bin/python3 run.py time --sitting "$S" --skin 0.7 --ranks $r --fluid GW --mass 0.001 --cell shardlow:0.0007 imp:0.001
done

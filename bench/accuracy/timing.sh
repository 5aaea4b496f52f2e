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
/usr/bin/python3 run.py time-matrix --ranks 1 "$@"
/usr/bin/python3 run.py time-matrix --ranks 2 "$@"

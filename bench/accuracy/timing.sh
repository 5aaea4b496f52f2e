#!/usr/bin/env bash
# Cost per time unit of every integrator of the scans at its largest step (results/timing.jsonl):
# alternated rounds of 400 steps from the equilibrated configuration, on 1 and then 2 ranks.
# Run on an otherwise quiet machine. Usage: bash bench/accuracy/timing.sh [run.py time-matrix options]
set -u
cd "$(dirname "$0")"
/usr/bin/python3 run.py time-matrix --ranks 1 "$@"
/usr/bin/python3 run.py time-matrix --ranks 2 "$@"

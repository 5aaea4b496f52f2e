#!/usr/bin/env bash
# Cost per atom-step from about 3,000 to 200,000 atoms (one LAMMPS run per size, all styles side
# by side, 1 rank). Usage: bash bench/run_scaling.sh [steps]   (writes the logs to bench/results/scaling/, the table to bench/results/scaling.md)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
. "$here/tools/lammps_env.sh"
steps=${1:-100}
out="$here/bench/results/scaling"
mkdir -p "$out"
for side in 10 20 30 40; do    # 3,000, 24,000, 81,000, 192,000 atoms
  "$LMP" -in "$here/bench/in.scaling" -var plugin "$PLUGIN" -var side $side \
    -var steps "$steps" -log "$out/log.side$side" -screen none
done
/usr/bin/python3 - "$out" <<'PY' | tee "$out/../scaling.md"    # the summary; the logs are not kept
import glob, re, sys
rows = {}
for path in sorted(glob.glob(sys.argv[1] + "/log.side*"), key=lambda p: int(p.split("side")[1])):
    text = open(path).read()
    for block in re.split(r"^BENCH ", text, flags=re.M)[1:]:
        label = block.splitlines()[0].strip()
        m = re.search(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", block)
        seconds, steps, atoms = float(m.group(1)), int(m.group(2)), int(m.group(3))
        rows.setdefault(label, []).append((atoms, 1e9 * seconds / (steps * atoms)))
sizes = [a for a, _ in next(iter(rows.values()))]
print("| style | " + " | ".join(f"{a:,} atoms" for a in sizes) + " |")
print("|---|" + "---|" * len(sizes))
for label, values in rows.items():
    print(f"| {label} | " + " | ".join(f"{c:.0f} ns" for _, c in values) + " |")
PY

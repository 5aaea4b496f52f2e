"""Readers for LAMMPS output files shared by the post-processing scripts."""
import numpy as np


def read_blocks(path):
    """Blocks of a fix ave/chunk or ave/time (mode vector) file: list of (step, rows), rows an
    array with one line per chunk or row. A last block cut short (a run still writing) is left out."""
    blocks, rows, step, left = [], [], None, 0
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            fields = line.split()
            if left == 0:
                if rows:
                    blocks.append((step, np.array(rows)))
                step, left, rows = int(fields[0]), int(fields[1]), []
                continue
            rows.append([float(x) for x in fields])
            left -= 1
    if rows and left == 0:
        blocks.append((step, np.array(rows)))
    return blocks

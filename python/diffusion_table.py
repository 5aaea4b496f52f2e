#!/usr/bin/env python3
"""D from MSD and VACF (validation/diffusion/in.diffusion output) and the Schmidt number, one row per run (command line of etddpd.diffusion_table)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.diffusion_table import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

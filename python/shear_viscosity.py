#!/usr/bin/env python3
"""Steady-shear viscosity table and plot from validation/shear/results/results.dat. (command line of etddpd.shear_viscosity)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.shear_viscosity import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

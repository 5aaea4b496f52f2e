#!/usr/bin/env python3
"""Wavelength-dependent viscosity from transverse-current autocorrelations (TCAF). (command line of etddpd.tcaf_fit)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.tcaf_fit import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

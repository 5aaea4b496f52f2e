#!/usr/bin/env python3
"""Viscosity from a reverse-Poiseuille profile written by validation/implicit/in.reverse_poiseuille. (command line of etddpd.viscosity_fit)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.viscosity_fit import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

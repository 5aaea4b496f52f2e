#!/usr/bin/env python3
"""Markdown tables of equilibrium kBT against time step (validation/temperature/run.sh output), one per mass, (command line of etddpd.temperature_table)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.temperature_table import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

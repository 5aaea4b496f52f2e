#!/usr/bin/env python3
"""Summarise a LAMMPS log: mean temperature of the last run, throughput, where outputs went. (command line of etddpd.summarise_log)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.summarise_log import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""A study's records (small LAMMPS output files) in one JSON file. (command line of etddpd.study_records)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.study_records import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Profiles of the wall-bounded flow examples (examples/couette, examples/poiseuille). (command line of etddpd.flow_profiles)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.flow_profiles import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

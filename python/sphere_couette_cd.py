#!/usr/bin/env python3
"""Drag coefficient against the Reynolds number from a mass scan of examples/sphere-couette (command line of etddpd.sphere_couette_cd)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.sphere_couette_cd import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

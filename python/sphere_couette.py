#!/usr/bin/env python3
"""Post-process examples/sphere-couette: drag on the sphere and its conservative, dissipative and (command line of etddpd.sphere_couette)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.sphere_couette import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

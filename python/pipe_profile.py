#!/usr/bin/env python3
"""Post-process examples/pipe: fit the Hagen-Poiseuille parabola u_x = A - B r^2 to the axial (command line of etddpd.pipe_profile)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.pipe_profile import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

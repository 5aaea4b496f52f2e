#!/usr/bin/env python3
"""Size scan of examples/sphere-couette: drag per box size over independent runs, extrapolated to the paper's box. (command line of etddpd.sphere_couette_sizes)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.sphere_couette_sizes import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

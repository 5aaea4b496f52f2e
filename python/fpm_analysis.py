#!/usr/bin/env python3
"""Post-processing of the dpd/fpm validation runs (validation/fpm/run.sh). (command line of etddpd.fpm_analysis)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.fpm_analysis import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

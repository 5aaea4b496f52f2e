#!/usr/bin/env python3
"""The two-sphere torque of dpd/fpm from the fluid's fields (command line of etddpd.fpm_torque_field)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.fpm_torque_field import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Drag on a sphere in the channel examples (examples/channel-sphere): Re, C_D and their errors. (command line of etddpd.channel_sphere)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.channel_sphere import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Tables and error-against-dt plots of the accuracy matrix (command line of etddpd.accuracy_matrix)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from etddpd.accuracy_matrix import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())

"""``python -m meceng``: the same command line as ``meceng``."""

import sys

from meceng.cli import main

if __name__ == "__main__":
    sys.exit(main())

"""``python -m meceng``: the same command line as ``meceng``."""

from meceng.cli import console_main

if __name__ == "__main__":
    console_main()

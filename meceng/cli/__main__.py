"""``python -m meceng.cli``: the same as the ``meceng`` command."""

from meceng.cli import console_main

if __name__ == "__main__":
    console_main()

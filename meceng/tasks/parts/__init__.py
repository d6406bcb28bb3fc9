"""Level 3a part models (ids 51-72), one module each, plus the master parameters of each family."""

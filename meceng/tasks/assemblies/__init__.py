"""Level 3b assembly models (ids 73-84), one module each, on the level 3a parts."""

"""Level 4: the design task models (one module each, see :mod:`meceng.tasks.design_base`)."""

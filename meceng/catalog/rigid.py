"""Level 1-2 components: mass points, rigid bodies, springs, joints, loads, contacts and sensors.

Each component teaches one Exudyn 1.13 building block the way the ground truths in
``meceng.tasks`` are written: the high-level ``mbs.Create*`` functions with ``itemNumbers=``,
``mass=``, ``inertia=`` and ``gravity=``. Every example is a complete program (the standard
preamble, the model, ``mbs.Assemble()`` and the standard simulation block) that runs in well under
a second and writes no file; ``tests/test_catalog.py`` runs them all.
"""

from __future__ import annotations

from meceng.catalog.bodies import GROUND, INERTIA_CUBOID, INERTIA_CYLINDER, INERTIA_SPHERE, MASS_POINT, RIGID_BODY
from meceng.catalog.component import Component
from meceng.catalog.joints import GENERIC_JOINT, PRISMATIC_JOINT, REVOLUTE_JOINT, ROLLING_DISC, SPHERICAL_JOINT
from meceng.catalog.loads import (
    FORCE,
    JOINT_PD_CONTROL,
    LOAD_USER_FUNCTION,
    SENSOR,
    SPHERE_SPHERE_CONTACT,
    SPHERE_TRIANGLE_CONTACT,
    TORQUE,
)
from meceng.catalog.springs import (
    CARTESIAN_SPRING_DAMPER,
    COORDINATE_CONSTRAINT,
    COORDINATE_SPRING_DAMPER,
    DISTANCE_CONSTRAINT,
    RIGID_BODY_SPRING_DAMPER,
    SPRING_DAMPER,
    TORSIONAL_SPRING_DAMPER,
)

COMPONENTS: tuple[Component, ...] = (
    GROUND,
    MASS_POINT,
    RIGID_BODY,
    INERTIA_CUBOID,
    INERTIA_CYLINDER,
    INERTIA_SPHERE,
    SPRING_DAMPER,
    CARTESIAN_SPRING_DAMPER,
    TORSIONAL_SPRING_DAMPER,
    RIGID_BODY_SPRING_DAMPER,
    DISTANCE_CONSTRAINT,
    COORDINATE_SPRING_DAMPER,
    COORDINATE_CONSTRAINT,
    REVOLUTE_JOINT,
    PRISMATIC_JOINT,
    SPHERICAL_JOINT,
    GENERIC_JOINT,
    ROLLING_DISC,
    FORCE,
    TORQUE,
    LOAD_USER_FUNCTION,
    SPHERE_SPHERE_CONTACT,
    SPHERE_TRIANGLE_CONTACT,
    SENSOR,
    JOINT_PD_CONTROL,
)

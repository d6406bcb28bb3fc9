"""Task 30 (level 1): double pendulum / rigid bodies — two cuboid links on revolute joints about z,
swinging in the x-y plane under gravity.

Both links are homogeneous cuboids with the long side along their local x-axis; the first hangs at
ground point [0, 0, 0], the second at the end of the first. Both start from rest, aligned, at an
angle phi0 below the horizontal. A double pendulum is chaotic at high energy; phi0 is limited to
35-80 degrees below the horizontal (10-55 degrees from the downward vertical) and the end time to
2 s, a regime where a re-ordered but correct model stays well within the 1e-5 solution tolerance.

Physics checks: the trajectory agrees with an independent RK4 integration of the planar equations
of motion of two physical pendulum links; the total energy is conserved (no damping); the joints
keep the links connected.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=30,
    name="double pendulum / rigid bodies",
    level="1",
    description="""
        A double pendulum modeled with two rigid links and two revolute joints, moving in the x-y
        plane. Both links are homogeneous cuboids (bricks) with density rho = {density} kg/m^3:
        link 1 has side lengths [L1, w, h] = [{length1}, {width}, {thickness}] m and link 2 has side
        lengths [L2, w, h] = [{length2}, {width}, {thickness}] m along their local x-, y- and
        z-axes, i.e. the long side is the local x-axis; their inertias are computed with
        InertiaCuboid(density=rho, sideLengths=...), so each link's reference point is its center of
        mass. Initially both links are aligned and point from the ground point [0, 0, 0] downwards
        to the right at the angle phi0 = {angle_deg} degrees below the positive x-axis (converted
        to radians), with unit direction e = [cos(phi0), -sin(phi0), 0]. Link 1's reference
        position is L1/2*e and link 2's reference position is (L1 + L2/2)*e; both have the
        reference rotation matrix RotationMatrixZ(-phi0), so that their local x-axes point along e.
        Revolute joint 1 between ground and link 1 is located at [0, 0, 0] and revolute joint 2
        between link 1 and link 2 at L1*e, both with the rotation axis [0, 0, 1] (global
        coordinates). Both links start from rest. Gravity g = {gravity} m/s^2 acts in the negative
        y-direction on both links; no other forces and no damping. Create the ground, link 1,
        link 2, revolute joint 1 and then revolute joint 2.
    """,
    open_description="""
        A planar double pendulum of two rigid bars swinging in the x-y plane. Both bars are
        homogeneous with density {density} kg/m^3 and a rectangular cross-section: bar 1 has length
        L1 = {length1} m, bar 2 length L2 = {length2} m, both have width {width} m (in the x-y
        plane, across the bar) and thickness {thickness} m (along the global z-axis). Bar 1 is
        pinned at one end to the fixed world at the origin [0, 0, 0] by a frictionless hinge whose
        axis is the global z-axis; bar 2 is pinned by a second frictionless hinge, also about the
        z-axis, to the free end of bar 1, and its own other end is free. At the start both bars lie
        on one straight line that runs from the origin downwards to the right, at the angle
        {angle_deg} degrees below the positive x-axis (towards +x and -y): bar 1 spans the first L1
        of that line, bar 2 the next L2. Both bars start from rest. Gravity g = {gravity} m/s^2
        acts in the negative y-direction; there is no damping and no other force.
    """,
    params=(
        Param("density", 500.0, 8000.0, "kg/m^3"),
        Param("length1", 0.3, 1.0, "m"),
        Param("length2", 0.3, 1.0, "m"),
        Param("width", 0.02, 0.1, "m"),
        Param("thickness", 0.01, 0.05, "m"),
        Param("angle_deg", 35.0, 80.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCuboid", "RevoluteJoint"),
    model_code="""
        phi0 = angle_deg * np.pi / 180
        e = np.array([np.cos(phi0), -np.sin(phi0), 0])
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oLink1 = mbs.CreateRigidBody(referencePosition=0.5 * length1 * e,
                                     referenceRotationMatrix=RotationMatrixZ(-phi0),
                                     inertia=InertiaCuboid(density=density,
                                                           sideLengths=[length1, width, thickness]),
                                     gravity=[0, -gravity, 0])
        oLink2 = mbs.CreateRigidBody(referencePosition=(length1 + 0.5 * length2) * e,
                                     referenceRotationMatrix=RotationMatrixZ(-phi0),
                                     inertia=InertiaCuboid(density=density,
                                                           sideLengths=[length2, width, thickness]),
                                     gravity=[0, -gravity, 0])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oLink1], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateRevoluteJoint(itemNumbers=[oLink1, oLink2], position=length1 * e, axis=[0, 0, 1])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)

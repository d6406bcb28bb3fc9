"""Task 16 (level 1): inverted single pendulum — an uncontrolled pendulum on a cart (two mass
points), released upright and pushed over by a small constant disturbance force.

The cart is a mass point on ground that a spherical joint lets move only along x
(constrainedAxes = [0, 1, 1]); the pendulum mass sits upright on a massless rod (distance
constraint) and a small constant force in x makes it fall over. Decision on regularity: no
stabilising spring; the fall itself is simulated. With the cart coordinate eliminated, the
pendulum angle obeys an autonomous one-degree-of-freedom equation, so the motion (fall, swing
through the bottom, rise on the other side) is regular and not chaotic. Round-off that differs
between equivalent models is amplified at most by exp(lambda*T) during the unstable phase
(lambda = sqrt(g*(M+m)/(M*L)) <= 7.1 1/s here, T = 2 s, factor < 2e6 on ~1e-16): far below the 1e-5
tolerance. The force range (at least 1 % of the pendulum weight) makes the pendulum fall past the
horizontal within the 2 s for every draw.

Physics check: the trajectory agrees with an independent RK4 integration of the cart-pendulum
equations of motion; the rod length is kept and the cart stays on the x-axis.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=16,
    name="inverted single pendulum",
    level="1",
    description="""
        An inverted pendulum on a cart, modeled with two mass points and no control. The cart is a
        mass point with mass m1 = {cart_mass} kg at the reference position [0, 0, 0]; it is
        attached to ground by a spherical joint at [0, 0, 0] that constrains only the y- and
        z-translations (constrainedAxes = [0, 1, 1]), so the cart can move freely along the x-axis.
        The pendulum is a mass point with mass m2 = {pendulum_mass} kg that starts in the upright
        position at [0, {length}, 0], i.e. on the positive y-axis directly above the cart; it is
        connected to the cart by a massless rigid rod of length L = {length} m, modeled as a
        distance constraint between cart and pendulum mass. Both start from rest. A constant
        disturbance force [{force}, 0, 0] N in x-direction acts on the pendulum mass. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction on both mass points. Create the ground,
        the cart, the pendulum mass, the spherical joint, the distance constraint and then the
        force.
    """,
    open_description="""
        An uncontrolled inverted pendulum on a cart, both idealised as point masses. The cart, a
        point mass of m1 = {cart_mass} kg, starts at the origin [0, 0, 0] and slides without
        friction along the global x-axis only: its y- and z-coordinates stay zero. The pendulum
        bob, a point mass of m2 = {pendulum_mass} kg, is joined to the cart by a massless rigid
        rod of length L = {length} m, pinned without friction at both ends (the rod only keeps the
        distance between cart and bob at L). At the start the bob stands upright at [0, {length},
        0], directly above the cart, and both are at rest. A constant force of {force} N in the
        positive x-direction acts on the bob. Gravity g = {gravity} m/s^2 acts in the negative
        y-direction on both point masses.
    """,
    params=(
        Param("cart_mass", 1.0, 5.0, "kg"),
        Param("pendulum_mass", 0.1, 0.5, "kg"),
        Param("length", 0.3, 1.0, "m"),
        Param("force", 0.05, 0.3, "N"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SphericalJoint", "DistanceConstraint", "Force"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oCart = mbs.CreateMassPoint(referencePosition=[0, 0, 0], mass=cart_mass, gravity=[0, -gravity, 0])
        oPendulum = mbs.CreateMassPoint(referencePosition=[0, length, 0], mass=pendulum_mass,
                                        gravity=[0, -gravity, 0])
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oCart], position=[0, 0, 0], constrainedAxes=[0, 1, 1])
        mbs.CreateDistanceConstraint(itemNumbers=[oCart, oPendulum], distance=length)
        mbs.CreateForce(itemNumber=oPendulum, loadVector=[force, 0, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)

"""Task 410 (level 4): the member stiffness that limits a Pratt truss's largest deflection under a
suddenly applied load.

The system is task 38's Pratt truss bridge (point-mass nodes, spring-damper members, pinned and
roller supports), loaded at t = 0 by gravity and a force at the bottom node B_1; the members' axial
stiffness k is left open. The spec is an extreme: the largest downward displacement of the loaded
node B_1 over the run. The truss is linear, but the response is the sum of many modes with
different frequencies and damping (the member dampers, and the solver's numerical damping of the
highest ones): the modes do not peak together, so the peak is not twice the static deflection.

Estimate: the static deflection of the determinate truss (method of joints / unit load, gravity on
every node and the force at B_1), delta_s = C / k, times the dynamic factor 2 of a suddenly applied
load on an undamped oscillator: k = 2 C / target.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.pratt_truss_bridge_frame_with_springs import TASK as TRUSS


def largest_deflection(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return float(np.max(-q[:, 4]))  # B_1 is the second mass point: columns 3..5, y in 4


def static_deflection_unit_stiffness(values: dict) -> float:
    """The static downward displacement of B_1 with k = 1 N/m (linear, small displacements)."""
    n, a, h = int(values["n_panels"]), values["panel_length"], values["height"]
    nodes = [np.array([i * a, 0.0]) for i in range(n + 1)] + [np.array([i * a, h]) for i in range(1, n)]
    top = {i: n + i for i in range(1, n)}  # B_i is node i, T_i node n + i
    members = [(i, i + 1) for i in range(n)] + [(top[i], top[i + 1]) for i in range(1, n - 1)]
    members += [(0, top[1]), (top[n - 1], n)] + [(i, top[i]) for i in range(1, n)]
    members += [(top[i], i + 1) for i in range(1, n // 2)] + [(top[i], i - 1) for i in range(n // 2 + 1, n)]
    stiffness = np.zeros((2 * len(nodes), 2 * len(nodes)))
    for i, j in members:
        e = (nodes[j] - nodes[i]) / np.linalg.norm(nodes[j] - nodes[i])
        block = np.outer(e, e)
        for r, c, sign in ((i, i, 1), (j, j, 1), (i, j, -1), (j, i, -1)):
            stiffness[2 * r:2 * r + 2, 2 * c:2 * c + 2] += sign * block
    load = np.zeros(2 * len(nodes))
    load[1::2] = -values["node_mass"] * values["gravity"]
    load[3] -= values["force"]
    free = [k for k in range(2 * len(nodes)) if k not in (0, 1, 2 * n + 1)]
    u = np.linalg.solve(stiffness[np.ix_(free, free)], load[free])
    return float(-u[free.index(3)])


def estimate(values: dict, target: float) -> dict[str, float]:
    return {"stiffness": 2.0 * static_deflection_unit_stiffness(values) / target}


TASK = DesignModel(
    id=410,
    name="truss largest deflection",
    system=TRUSS,
    open_description=TRUSS.open_description.replace("k = {stiffness} N/m", "k"),
    params=(
        Param("half_panels", 2, 4, integer=True),
        Param("panel_length", 0.5, 1.0, "m"),
        Param("height", 0.6, 1.2, "m"),
        Param("node_mass", 1.0, 5.0, "kg"),
        Param("damping", 50.0, 500.0, "N*s/m"),
        Param("force", 500.0, 5000.0, "N"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    derive=TRUSS.derive,
    variables=(DesignVariable("stiffness", 2e6, 1e7, "N/m", "the axial stiffness k of every member"),),
    spec=Spec("the largest downward displacement of the loaded bottom node B_1 over the run", "extreme", "m",
              largest_deflection),
    spec_text="""the largest downward displacement of the loaded bottom node B_1 from its initial position,
        over the simulated time, is {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="static deflection of the determinate truss (method of joints, unit load) times the dynamic "
                  "factor 2 of a suddenly applied load: k = 2 C / target with delta_static = C / k",
)

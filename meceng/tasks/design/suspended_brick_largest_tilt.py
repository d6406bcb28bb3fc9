"""Task 430 (level 4): the horizontal stiffness of a brick's four elastic mounts that limits its
largest tilt.

The system is task 24's brick hung at its four upper corners on spring-dampers to the fixed world,
pushed sideways at the start in both horizontal directions; the mounts' horizontal stiffness kh is
left open. The spec is an extreme: the largest tilt of the brick (the angle between its edge b and
the vertical) over the run.

Why a closed form misses: the mounts sit above the centre of mass, so each push excites two coupled
modes of sway and rocking in its own vertical plane, four modes in all with four frequencies (the
edges a and c differ); the tilt is the two planes' rocking combined, and its largest value over the
run is where four lightly damped oscillations happen to add up, at an instant that only the coupled
motion gives.

Estimate: each plane uncoupled: the brick sways on the four horizontal springs (w = sqrt(4 kh / m),
largest sway v / w) and rocks quasi-statically under the springs' force, which acts b/2 above the
centre, against the rocking stiffness of the vertical springs (arm a/2 or c/2) and the horizontal
ones (arm b/2); the two planes' largest tilts added as if they peaked together.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec, closest_on_grid
from meceng.tasks.design_measures import body_axis
from meceng.tasks.suspended_rigid_body import TASK as BRICK

KH_RANGE = (1000.0, 5000.0)


def largest_tilt(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    up = body_axis(q, 3, 1)[:, 1]  # position in columns 0..2, Euler parameters 3..6; the edge b's vertical part
    return float(np.degrees(np.max(np.arccos(np.clip(up, -1.0, 1.0)))))


def _tilt(values: dict, kh: float) -> float:
    a, b, c = values["size_x"], values["size_y"], values["size_z"]
    m, kv = values["density"] * a * b * c, values["stiffness_v"]
    sway = np.sqrt(4.0 * kh / m)
    tilts = []
    for v, arm in ((values["vel_x"], a), (values["vel_z"], c)):
        force = 4.0 * kh * v / sway
        rocking = 4.0 * kv * (arm / 2) ** 2 + 4.0 * kh * (b / 2) ** 2
        tilts.append(force * (b / 2) / rocking)
    return float(np.degrees(np.hypot(*tilts)))


def estimate(values: dict, target: float) -> dict[str, float]:
    grid = np.geomspace(*KH_RANGE, 2001)  # the estimated tilt rises and falls with kh: the closest in range
    return {"stiffness_h": closest_on_grid(grid, lambda kh: _tilt(values, kh), target)}


TASK = DesignModel(
    id=430,
    name="suspended brick largest tilt",
    system=BRICK,
    open_description=BRICK.open_description.replace("The stiffness is {stiffness_h} N/m in the\n        horizontal",
                                                    "The stiffness is kh in the\n        horizontal"),
    params=(*(p for p in BRICK.params if p.name not in ("stiffness_h", "damping")),
            Param("damping", 0.0, 20.0, "N*s/m")),
    variables=(DesignVariable("stiffness_h", *KH_RANGE, "N/m", "the horizontal stiffness kh of every mount"),),
    spec=Spec("the largest tilt of the brick (the angle between its edge b and the vertical) over the run",
              "extreme", "deg", largest_tilt),
    spec_text="""the brick tilts at most {target} degrees over the simulated time: the largest angle between
        its edge of length b (vertical at the start) and the vertical is {target} degrees, within
        ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="each vertical plane uncoupled: the sway on the horizontal springs (largest sway v / w), the "
                  "rocking quasi-static under the springs' force b/2 above the centre; the two planes' tilts added "
                  "as if they peaked together",
)

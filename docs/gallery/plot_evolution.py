"""
Stick zone over a cycle, exact and marched
==========================================

The paper's Figure 6 for the reference cycle: the contact edge, the exact stick boundary and its
asymptotic estimate along both halves of the cycle, with the stick zone of a numerical time march
(120 cells, three cycles after a normal-first ramp) overlaid at each increment of its last cycle.
The march lands on the exact boundary to within a cell.
"""

import halfplane
import halfplane.plot

case = halfplane.Case(
    youngs_modulus=200e3, poisson_ratio=0.3, friction=0.6, profile="hertz", radius=50.0,
    point1=(1000.0, -250.0, -20.0), point2=(1400.0, 250.0, 20.0),
    history={"kind": "cycle", "cycles": 3, "steps_per_half": 45, "ramp_steps": 15},
)
marched = halfplane.march(case, cells=120)
print(marched)
halfplane.plot.evolution(halfplane.evolve(case, points=41), marched)

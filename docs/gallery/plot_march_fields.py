"""
Traction and slip along the contact
===================================

A flat punch with rounded edges (b = 0.3 mm, R = 50 mm) under the reference cycle, marched with
200 cells and its fields recorded: the shear traction q with the friction limits +/- f p, and the
accumulated slip, at a quarter, a half, three quarters and the end of the last cycle. Where
``|q| = f p`` the contact slips; inside the stick zone the slip does not change.
"""

import halfplane
import halfplane.plot

case = halfplane.Case(
    youngs_modulus=200e3, poisson_ratio=0.3, friction=0.6, profile="flat-rounded",
    flat_half_width=0.3, radius=50.0, point1=(1000.0, -250.0, -20.0),
    point2=(1400.0, 250.0, 20.0),
    history={"kind": "cycle", "cycles": 3, "steps_per_half": 45, "ramp_steps": 15},
)
marched = halfplane.march(case, cells=200, fields=True)
halfplane.plot.march_fields(marched, friction=case.friction)

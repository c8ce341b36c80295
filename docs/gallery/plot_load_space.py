"""
Load space of the reference cycle
=================================

The Hertz cycle of the theory page (R = 50 mm, E = 200 GPa, nu = 0.3, f = 0.6) from
(P, Q, sigma) = (1000 N/mm, -250 N/mm, -20 MPa) to (1400, 250, 20): its trajectory in P-Q with the
friction lines, and the equivalent shear S = Q +/- pi a sigma/4 of each edge against P. The paths
of S follow the contact half-width a(P), taken from the stick-zone evolution along the cycle.
"""

import halfplane
import halfplane.plot

case = halfplane.Case(
    youngs_modulus=200e3, poisson_ratio=0.3, friction=0.6, profile="hertz", radius=50.0,
    point1=(1000.0, -250.0, -20.0), point2=(1400.0, 250.0, 20.0),
)
result = halfplane.steady(case)
print(result)
halfplane.plot.load_space(result, halfplane.evolve(case, points=41))

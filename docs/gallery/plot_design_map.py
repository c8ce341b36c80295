"""
A design map over the shear and normal loads
============================================

Hertz contacts under cycles from (1000 N/mm, 0, 0) to (P2, Q2, 0) on a 61 x 41 grid of Q2 and P2,
solved in one :func:`halfplane.steady_batch` call: the regime of each case, then the right slip
zone at point 1 as colour (blank where the contact slides as a whole). Each cell is one case.
"""

import numpy as np
import pandas as pd

import halfplane
import halfplane.plot

q2, p2 = np.meshgrid(np.linspace(0.0, 900.0, 61), np.linspace(800.0, 1600.0, 41))
table = pd.DataFrame({"shear2": q2.ravel(), "normal2": p2.ravel()}).assign(
    youngs_modulus=200e3, poisson_ratio=0.3, friction=0.6, profile="hertz", radius=50.0,
    normal1=1000.0, shear1=0.0, bulk1=0.0, bulk2=0.0,
)
frame = pd.concat([table, halfplane.steady_batch(table)], axis=1)
halfplane.plot.design_map(frame, "shear2", "normal2")

# %%
# The right slip zone at point 1, with its largest value marked:
halfplane.plot.design_map(frame, "shear2", "normal2", "slip_right_1")

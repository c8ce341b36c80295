"""
The paper's Figure 5 from one batch
===================================

The slip zone at the right edge of the smaller contact against the shear range, for
P2/P1 = 1, 1.2 and 1.5 and tension ranges 0, 0.02 and 0.05 per mm (f = 0.6, Hertz, P1 = 1000
N/mm): 531 cycles solved in one :func:`halfplane.steady_batch` call. With tension the curves stop
where slip would reverse inside a half-cycle, which the steady-state analysis does not cover.
"""

import itertools

import numpy as np
import pandas as pd

import halfplane
import halfplane.plot

P1, F = 1000.0, 0.6
rows = []
for ratio, tension, x in itertools.product([1.0, 1.2, 1.5], [0.0, 0.02, 0.05], np.arange(1, 60) / 60):
    p2 = ratio * P1
    dq = x * F * (P1 + p2) / 2
    rows.append((P1, -dq / 2, tension * P1 / 2, p2, dq / 2, -tension * P1 / 2))
cases = pd.DataFrame(rows, columns=["normal1", "shear1", "bulk1", "normal2", "shear2", "bulk2"])
cases = cases.assign(youngs_modulus=200e3, poisson_ratio=0.3, friction=F, profile="hertz", radius=50.0)
halfplane.plot.slip_map(cases, halfplane.steady_batch(cases))

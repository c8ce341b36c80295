"""
Stress below the contact
========================

The bundled fretting-fatigue case (Hertz pad, constant P = 1000 N/mm, Q and the bulk stress in
phase between (-300, -60) and (300, 60)): sigma_xx below the contact at the increment where Q and
the bulk stress peak, on a grid over +/-1.5 a and down to a. The tensile peak sits at the
trailing edge of the contact, on the surface.
"""

import numpy as np

import halfplane
import halfplane.plot

case = halfplane.Case(
    youngs_modulus=200e3, poisson_ratio=0.3, friction=0.6, profile="hertz", radius=50.0,
    point1=(1000.0, -300.0, -60.0), point2=(1000.0, 300.0, 60.0),
    history={"kind": "cycle", "cycles": 2, "steps_per_half": 30, "ramp": "normal-first",
             "ramp_steps": 10},
)
a = halfplane.steady(case).contact.half_width_2
x = np.linspace(-1.5 * a, 1.5 * a, 121)
z = np.linspace(0.0, a, 61)
below = halfplane.stress(case, x=x[None, :], z=z[:, None], step=110, cells=200)
halfplane.plot.stress_map(below, component="sxx")

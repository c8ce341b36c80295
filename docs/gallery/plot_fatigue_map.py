"""
Where the fatigue parameters peak
=================================

The same case with the illustrative steel constants of ``examples/fatigue.toml``: each
initiation parameter's maximum over the steady cycle, the critical plane through it and the line
the line method averages over (0 <= z <= 2L, L the critical distance). They all peak on the
surface at the trailing edge of the contact.
"""

import halfplane
import halfplane.plot

case = halfplane.Case.from_toml("""
[material]
youngs_modulus = 200000.0
poisson_ratio = 0.3
[friction]
coefficient = 0.6
[profile]
kind = "hertz"
radius = 50.0
[cycle]
point1 = { normal = 1000.0, shear = -300.0, bulk = -60.0 }
point2 = { normal = 1000.0, shear = 300.0, bulk = 60.0 }
[history]
kind = "cycle"
cycles = 2
steps_per_half = 30
ramp = "normal-first"
ramp_steps = 10
[fatigue]
fatigue_strength = 1800.0
fatigue_strength_exponent = -0.1
fatigue_ductility = 0.5
fatigue_ductility_exponent = -0.6
shear_fatigue_strength = 1040.0
shear_fatigue_ductility = 0.87
fatemi_socie_k = 0.5
findley_k = 0.25
crossland_alpha = 0.4
yield_stress = 900.0
threshold = 160.0
endurance_range = 700.0
axial_fatigue_limit = 350.0
torsional_fatigue_limit = 220.0
mcdiarmid_shear_limit = 220.0
ultimate_strength = 1200.0
nx = 40
nz = 20
""")
result = halfplane.fatigue(case, cells=200)
print(result.parameters[["parameter", "value", "x", "z", "plane"]])
a = halfplane.steady(case).contact.half_width_1
halfplane.plot.fatigue_map(result, ["swt", "fatemi_socie", "findley", "mwcm"], half_width=a)

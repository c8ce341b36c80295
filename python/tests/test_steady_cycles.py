"""`history.cycles = "steady"` from Python (issue 17, item 3): `halfplane.march` repeats the
cycle until the slip ranges repeat and says how many cycles it took."""

from __future__ import annotations

import pytest

import halfplane

#: The issue's case: the normal-first ramp leaves cells at the friction limit inside the permanent
#: stick zone, which shake down about 10x per cycle (docs/convergence.md, "The steady cycle").
SHAKEDOWN = dict(
    youngs_modulus=197783.0,
    poisson_ratio=0.163,
    friction=1.048,
    profile="hertz",
    radius=27.83,
    point1=(1972.57, 1157.01, -17.21),
    point2=(1302.01, 426.22, 10.44),
    cells=400,
)


def history(cycles, **extra):
    return {
        "kind": "cycle",
        "cycles": cycles,
        "steps_per_half": 20,
        "ramp": "normal-first",
        "ramp_steps": 19,
        **extra,
    }


def test_march_until_steady_finds_the_steady_stick_zone_and_the_cycle_count():
    case = halfplane.Case(**SHAKEDOWN, history=history("steady"))
    assert "cycles until steady (at most 1000)" in repr(case)
    marched = halfplane.march(case)
    assert marched.steady_converged is True
    assert marched.steady_change <= 1e-10
    assert marched.cycles_run == len(marched.cycles) >= 4
    exact = halfplane.steady(case).stick_zone
    cell = marched.x[1] - marched.x[0]
    last = marched.steps.iloc[-1]
    left, right = last["stick_left"], last["stick_right"]
    # Half-width and centre within 0.2 cells of the steady analysis (the march's ends are cell
    # edges, so each end alone is only within half a cell in general).
    d, e = (right - left) / 2, (right + left) / 2
    exact_d, exact_e = (exact.right - exact.left) / 2, (exact.right + exact.left) / 2
    assert abs(d - exact_d) <= 0.2 * cell
    assert abs(e - exact_e) <= 0.2 * cell
    # The same number of cycles, given: the same march; one fewer has not converged.
    fixed = halfplane.march(
        halfplane.Case(**SHAKEDOWN, history=history(marched.cycles_run))
    )
    assert fixed.steps.equals(marched.steps)
    assert fixed.steady_converged is True
    fewer = halfplane.march(
        halfplane.Case(**SHAKEDOWN, history=history(marched.cycles_run - 1))
    )
    assert fewer.steady_converged is False


def test_a_march_that_does_not_repeat_within_max_cycles_raises_naming_the_change():
    case = halfplane.Case(**SHAKEDOWN, history=history("steady", max_cycles=3))
    with pytest.raises(halfplane.SolverError) as raised:
        halfplane.march(case)
    assert raised.value.variant == "NotSteady"
    assert "history.max_cycles = 3" in str(raised.value)
    with pytest.raises(halfplane.InputError, match="history.max_cycles"):
        halfplane.Case(**SHAKEDOWN, history=history(3, max_cycles=10))
    with pytest.raises(halfplane.InputError, match="history.steady_tolerance"):
        halfplane.Case(**SHAKEDOWN, history=history("steady", steady_tolerance=2.0))

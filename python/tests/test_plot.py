"""halfplane.plot: each figure rendered with the Agg backend and its drawn data checked (lines,
contour levels, colour bars, labels), not its pixels. Where a figure derives numbers, they are
checked against an independent route: a closed form, the library's own value of the same
quantity, or the marching solver against the exact steady state."""

from __future__ import annotations

import math
import subprocess
import sys

import halfplane
import numpy as np
import pandas as pd
import pytest
from conftest import ROOT

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from halfplane import plot
from matplotlib.collections import PathCollection, QuadMesh
from matplotlib.contour import ContourSet

EXAMPLES = ROOT / "examples"


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def line(ax, label):
    """The Line2D of ``ax`` labelled ``label`` (exactly one)."""
    found = [ln for ln in ax.get_lines() if ln.get_label() == label]
    assert len(found) == 1, [ln.get_label() for ln in ax.get_lines()]
    return found[0]


def line_starting(ax, prefix):
    found = [ln for ln in ax.get_lines() if ln.get_label().startswith(prefix)]
    assert len(found) == 1, [ln.get_label() for ln in ax.get_lines()]
    return found[0]


@pytest.fixture(scope="module")
def hertz():
    case = halfplane.read_case(EXAMPLES / "hertz.toml")
    return halfplane.steady(case), halfplane.evolve(case, points=11)


@pytest.fixture(scope="module")
def marched():
    # The reference cycle at 100 cells: 300 increments, 3 cycles of 90 after a 30-step ramp.
    case = halfplane.read_case(EXAMPLES / "march-cycle.toml")
    return case, halfplane.evolve(case, points=21), halfplane.march(case, cells=100, fields=True)


def test_load_space_draws_the_trajectories_and_the_library_s_equivalent_shears(hertz):
    result, frame = hertz
    fig = plot.load_space(result, frame)
    pq, ps = fig.axes[:2]
    trajectory = line(pq, "trajectory")
    assert list(trajectory.get_xdata()) == [1000.0, 1400.0]
    assert list(trajectory.get_ydata()) == [-250.0, 250.0]
    friction = line_starting(pq, "friction lines")
    slope = friction.get_ydata()[1] / friction.get_xdata()[1]
    assert slope == pytest.approx(0.6, rel=1e-15)
    # The P-S paths end at the library's equivalent shear forces of the asymptotic analysis
    # (computed in Rust): 1e-12 relative, the rounding of a few operations.
    edges = result.asymptotic.edges
    for name, side in (("left edge S = Q + πaσ/4", "left"), ("right edge S = Q − πaσ/4", "right")):
        s = line(ps, name).get_ydata()
        assert len(s) == 11
        assert s[0] == pytest.approx(getattr(edges.at_point1, f"equivalent_shear_{side}"), rel=1e-12)
        assert s[-1] == pytest.approx(getattr(edges.at_point2, f"equivalent_shear_{side}"), rel=1e-12)
    assert pq.get_xlabel() == "normal load P (N/mm)" and ps.get_ylabel() == "equivalent shear S (N/mm)"
    assert pq.get_title() == "P–Q trajectory (partial-slip)"


def test_load_space_without_the_evolution_marks_the_ends_and_refuses_another_cycle(hertz):
    result, _ = hertz
    fig = plot.load_space(result)
    ends = line(fig.axes[1], "left edge S = Q + πaσ/4 (ends)")
    assert ends.get_ydata()[1] == pytest.approx(result.asymptotic.edges.at_point2.equivalent_shear_left, rel=1e-12)
    other = halfplane.evolve(halfplane.read_case(EXAMPLES / "flat-rounded.toml"), points=5)
    with pytest.raises(ValueError, match="not of the same cycle"):
        plot.load_space(result, other)


def fig5_table(frictions=(0.6,)):
    rows = []
    for f in frictions:
        for ratio in (1.0, 1.5):
            for tension in (0.0, 0.05):
                for x in np.arange(1, 20) / 20.0:
                    p1, p2 = 1000.0, 1000.0 * ratio
                    dq = x * f * 0.5 * (p1 + p2)
                    rows.append(dict(friction=f, normal1=p1, shear1=-dq / 2, bulk1=tension * p1 / 2,
                                     normal2=p2, shear2=dq / 2, bulk2=-tension * p1 / 2))
    return pd.DataFrame(rows).assign(youngs_modulus=200e3, poisson_ratio=0.3, profile="hertz", radius=50.0)


def test_slip_map_follows_the_hertz_closed_form():
    table = fig5_table()
    ax = plot.slip_map(table, halfplane.steady_batch(table))
    # P2 = P1 without tension: the stick zone is centred with d^2 = (AR/pi)(2 P0 - dQ/f) (paper
    # eq. (30)) and a0^2 = 2 P0 A R/pi, so y = 1 - sqrt(1 - x/2) exactly (1e-12: rounding). This
    # also checks a0, which the figure takes from a second batch at P0.
    plain = line(ax, "P2/P1 = 1, Δσ/P1 = 0/mm")
    x = np.asarray(plain.get_xdata())
    assert np.allclose(x, np.arange(1, 20) / 20.0, rtol=1e-12)
    assert np.allclose(plain.get_ydata(), 1.0 - np.sqrt(1.0 - x / 2.0), rtol=1e-12, atol=1e-12)
    # With tension the analysis stops before the full-stick limit: those points are gaps (NaN).
    tension = np.asarray(line(ax, "P2/P1 = 1.5, Δσ/P1 = 0.05/mm").get_ydata())
    assert np.isnan(tension).any() and np.isfinite(tension).any()
    assert len(ax.get_lines()) == 4
    assert ax.get_xlabel() == "shear range ΔQ/(f P0)" and ax.get_title() == "Slip-zone map, f = 0.6"


def test_slip_map_asks_which_friction_and_checks_its_inputs():
    table = fig5_table((0.3, 0.6))
    out = halfplane.steady_batch(table)
    with pytest.raises(ValueError, match="2 friction coefficients .*friction="):
        plot.slip_map(table, out)
    ax = plot.slip_map(table, out, friction=0.3)
    assert ax.get_title() == "Slip-zone map, f = 0.3"
    with pytest.raises(ValueError, match="invalid friction = 0.5"):
        plot.slip_map(table, out, friction=0.5)
    with pytest.raises(ValueError, match="lacks column.*'shear2'"):
        plot.slip_map(table.drop(columns="shear2"), out)
    with pytest.raises(ValueError, match="cases has 152 rows but results has 10"):
        plot.slip_map(table, out.head(10), friction=0.3)


def test_evolution_overlays_the_march_on_the_exact_stick_zone(marched):
    _, frame, march = marched
    fig = plot.evolution(frame, march)
    left, right = fig.axes[:2]
    t = frame.half - 1 + frame.fraction
    exact = line(right, "stick boundary (exact)")
    assert np.array_equal(exact.get_xdata(), t) and np.array_equal(exact.get_ydata(), frame.stick_right)
    assert np.array_equal(line(left, "contact edge").get_ydata(), -frame.half_width)
    assert np.array_equal(line(left, "stick boundary (asymptotic)").get_ydata(), frame.asymptotic_stick_left)
    # The last cycle: 90 increments at t = 2k/90. At the cycle's ends (t = 1: point 2; t = 2:
    # point 1) the marched stick zone is the permanent one [-m, n] of the exact analysis, to
    # within one cell (2 a_max/100), the marching solver's resolution.
    dots = line(right, "stick boundary (time marching)")
    assert np.allclose(dots.get_xdata(), 2.0 * np.arange(1, 91) / 90.0, rtol=1e-15)
    cell = 2.0 * frame.half_width.max() / 100
    for k, row in ((45, frame[(frame.half == 1)].iloc[-1]), (90, frame[(frame.half == 2)].iloc[-1])):
        assert abs(dots.get_ydata()[k - 1] - row.stick_right) < cell
        assert abs(line(left, "stick boundary (time marching)").get_ydata()[k - 1] - row.stick_left) < cell
    assert right.get_ylabel() == "position x (mm)"
    assert plot.evolution(frame, units={"length": "m"}).axes[0].get_ylabel() == "position x (m)"


def test_evolution_refuses_a_march_of_another_cycle(marched):
    _, frame, _ = marched
    other = halfplane.march(halfplane.read_case(EXAMPLES / "fatigue.toml"), cells=40)
    with pytest.raises(ValueError, match="not a march of the same cycle"):
        plot.evolution(frame, other)
    with pytest.raises(ValueError, match="invalid units key"):
        plot.evolution(frame, units={"lenght": "m"})


def test_march_fields_draws_the_fields_of_the_last_cycle_s_quarters(marched):
    _, _, march = marched
    fig = plot.march_fields(march, friction=0.6)
    top, bottom = fig.axes[:2]
    # The command's default increments for this history (README: 232, 255, 277 and 300).
    steps = [232, 255, 277, 300]
    assert [ln.get_label() for ln in bottom.get_lines() if ln.get_label().startswith("slip")] == [
        f"slip, step {s}" for s in steps
    ]
    for s in steps:
        q = line(top, f"q, step {s}").get_ydata()
        limit = line(top, f"±f p, step {s}").get_ydata()
        assert np.array_equal(q, march.traction[s - 1])
        assert np.array_equal(line(bottom, f"slip, step {s}").get_ydata(), march.slip[s - 1])
        assert np.array_equal(limit, 0.6 * march.pressure[s - 1])
        # Coulomb's law holds in what is drawn: |q| <= f p (to rounding, 1e-9 of the peak).
        assert np.all(np.abs(q) <= limit + 1e-9 * limit.max())
    assert top.get_ylabel() == "shear traction q (MPa)" and bottom.get_xlabel() == "position x (mm)"
    chosen = plot.march_fields(march, [10, 20])
    drawn = [ln.get_label() for ln in chosen.axes[0].get_lines() if not ln.get_label().startswith("_")]
    assert drawn == ["q, step 10", "q, step 20"]


def test_march_fields_checks_its_inputs(marched):
    case, _, march = marched
    with pytest.raises(ValueError, match="invalid steps value 301: the march has increments 1 to 300"):
        plot.march_fields(march, [1, 301])
    with pytest.raises(ValueError, match="1 to 20 can be drawn"):
        plot.march_fields(march, list(range(1, 22)))
    with pytest.raises(ValueError, match="fields=True"):
        plot.march_fields(halfplane.march(case, cells=20))


@pytest.fixture(scope="module")
def below():
    case = halfplane.read_case(EXAMPLES / "fatigue.toml")
    xs = np.linspace(-1.2, 1.2, 49)
    zs = np.linspace(0.0, 0.8, 17)
    return xs, zs, halfplane.stress(case, x=xs[None, :], z=zs[:, None], step=110, cells=100)


def filled_contours(ax):
    found = [c for c in ax.collections if isinstance(c, ContourSet) and c.filled]
    assert len(found) == 1
    return found[0]


def test_stress_map_fills_the_field_with_its_range_on_the_colour_bar(below):
    xs, zs, result = below
    ax = plot.stress_map(result, xs, zs, "sxx")
    filled = filled_contours(ax)
    # The colour scale runs exactly from the smallest to the largest value drawn.
    assert filled.levels[0] == result.sxx.min() and filled.levels[-1] == result.sxx.max()
    assert filled.colorbar.ax.get_ylabel() == "σxx (MPa)"
    assert filled.norm.vmin == result.sxx.min() and filled.norm.vmax == result.sxx.max()
    # The maximum is marked where it is, with its value in plain notation (4 figures).
    i, j = np.unravel_index(np.argmax(result.sxx), result.sxx.shape)
    star = line_starting(ax, "max σxx = ")
    assert (star.get_xdata()[0], star.get_ydata()[0]) == (xs[j], zs[i])
    value = float(star.get_label().split("= ")[1].split(" MPa")[0])
    assert value == pytest.approx(result.sxx.max(), rel=5e-4) and "e+" not in star.get_label()
    contact = line_starting(ax, "contact, a = ")
    assert list(contact.get_xdata()) == [-result.half_width, result.half_width]
    assert ax.get_aspect() == 1.0 and ax.yaxis_inverted()
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("position x (mm)", "depth z (mm)")
    # The result's own points (the broadcast x and z it keeps) draw the same map.
    own = filled_contours(plot.stress_map(result, component="sxx"))
    assert np.array_equal(result.x, np.broadcast_to(xs[None, :], result.sxx.shape))
    assert np.array_equal(result.z, np.broadcast_to(zs[:, None], result.sxx.shape))
    assert np.array_equal(own.levels, filled.levels)
    assert all(np.array_equal(p.vertices, q.vertices)
               for p, q in zip(own.get_paths(), filled.get_paths()))
    with pytest.raises(ValueError, match="give both x and z"):
        plot.stress_map(result, xs)
    # 2-D grids of the result's shape work the same.
    gx, gz = np.meshgrid(xs, zs)
    shear = plot.stress_map(result, gx, gz, "sxz")
    assert filled_contours(shear).levels[-1] == result.sxz.max()


def test_stress_map_checks_its_inputs(below):
    xs, zs, result = below
    with pytest.raises(ValueError, match="invalid component = 'sxy'"):
        plot.stress_map(result, xs, zs, "sxy")
    with pytest.raises(ValueError, match=r"do not span the result's grid \(17, 49\)"):
        plot.stress_map(result, zs, xs)
    with pytest.raises(ValueError, match="invalid levels"):
        plot.stress_map(result, xs, zs, levels=1)


def test_fatigue_map_marks_each_maximum_and_its_plane():
    case = halfplane.read_case(EXAMPLES / "fatigue.toml")
    result = halfplane.fatigue(case, cells=100)
    table = result.parameters
    a = halfplane.steady(case).contact.half_width_1
    ax = plot.fatigue_map(result, half_width=a)
    stars = [ln for ln in ax.get_lines() if ln.get_marker() == "*"]
    assert sorted((s.get_xdata()[0], s.get_ydata()[0]) for s in stars) == sorted(
        set(zip(table.x, table.z))
    )
    for row in table.itertuples():
        drawn = line_starting(ax, f"{row.parameter} = ")
        if np.isfinite(row.plane):
            # The line lies along the critical plane, through the maximum.
            x, z = drawn.get_xdata(), drawn.get_ydata()
            assert np.mean(x) == pytest.approx(row.x) and np.mean(z) == pytest.approx(row.z, abs=1e-12)
            angle = math.degrees(math.atan2(z[1] - z[0], x[1] - x[0])) % 180.0
            assert angle == pytest.approx(row.plane % 180.0, abs=1e-9)
    assert any(ln.get_label().startswith("mwcm = ") and " MPa" in ln.get_label() for ln in ax.get_lines())
    assert ax.get_aspect() == 1.0 and ax.yaxis_inverted()
    # The field under the maxima: the first drawn parameter with a map, over the whole grid.
    shaded = next(p for p in table.parameter if p in result.maps)
    filled = next(c for c in ax.collections if hasattr(c, "levels") and c.filled)
    values = result.maps[shaded]
    assert values.shape == (len(result.grid_z), len(result.grid_x))
    assert (filled.norm.vmin, filled.norm.vmax) == (values.min(), values.max())
    assert ax.get_xlim() == (result.grid_x.min(), result.grid_x.max())
    # Each parameter's reported maximum is the largest value of its map (the maps are what the
    # maxima are taken over, to the last bit).
    for name, values in result.maps.items():
        row = table[table.parameter == name].iloc[0]
        assert values.max() == row.value, name
    mwcm = plot.fatigue_map(result, field="mwcm")
    assert mwcm.get_title().endswith("shaded: mwcm")
    with pytest.raises(ValueError, match="invalid field = 'ruiz_f2'"):
        plot.fatigue_map(result, field="ruiz_f2")
    only = plot.fatigue_map(result, ["swt"])
    assert next(ln.get_label().split(" =")[0] for ln in only.get_lines() if "=" in ln.get_label()) == "swt"
    with pytest.raises(ValueError, match="invalid parameter 'wst'"):
        plot.fatigue_map(result, ["wst"])


@pytest.fixture(scope="module")
def design():
    shears = np.linspace(0.0, 600.0, 13)
    normals = np.array([1000.0, 1200.0, 1400.0])
    grid = pd.DataFrame([(q, p) for p in normals for q in shears], columns=["shear2", "normal2"])
    table = grid.assign(youngs_modulus=200e3, poisson_ratio=0.3, friction=0.6, profile="hertz",
                        radius=50.0, normal1=1000.0, shear1=0.0, bulk1=0.0, bulk2=0.0)
    return pd.concat([table, halfplane.steady_batch(table)], axis=1), shears, normals


def test_design_map_draws_each_case_as_a_cell_with_readable_axes(design):
    frame, shears, normals = design
    ax = plot.design_map(frame, "shear2", "normal2", "slip_right_1")
    mesh = next(c for c in ax.collections if isinstance(c, QuadMesh))
    expected = frame.slip_right_1.to_numpy().reshape(len(normals), len(shears))
    drawn = np.ma.filled(mesh.get_array().reshape(expected.shape).astype(float), np.nan)
    assert np.array_equal(drawn, expected, equal_nan=True)
    # Cells are centred on the cases: their edges lie midway between neighbouring values.
    assert np.isnan(expected).any() and np.isfinite(expected).any()
    assert mesh.colorbar.ax.get_ylabel() == "right slip zone at point 1 (mm)"
    assert mesh.norm.vmax == np.nanmax(expected)
    assert ax.get_xlabel() == "shear load Q at point 2 (N/mm)"
    assert ax.get_ylabel() == "normal load P at point 2 (N/mm)"
    star = line_starting(ax, "max ")
    k = int(np.nanargmax(frame.slip_right_1))
    assert (star.get_xdata()[0], star.get_ydata()[0]) == (frame.shear2[k], frame.normal2[k])
    # A sweep names its columns by dotted path: the same readable labels.
    renamed = frame.rename(columns={"shear2": "cycle.point2.shear", "normal2": "cycle.point2.normal"})
    ax = plot.design_map(renamed, "cycle.point2.shear", "cycle.point2.normal")
    assert ax.get_xlabel() == "shear load Q at point 2 (N/mm)"


def test_design_map_of_regimes_and_of_scattered_rows(design):
    frame, shears, normals = design
    ax = plot.design_map(frame, "shear2", "normal2")
    mesh = next(c for c in ax.collections if isinstance(c, QuadMesh))
    names = ["full-stick", "partial-slip", "gross-sliding", ""]
    codes = np.array([names.index(r) for r in frame.regime]).reshape(len(normals), len(shears))
    assert np.array_equal(np.asarray(mesh.get_array()).reshape(codes.shape), codes)
    assert sorted(t.get_text() for t in ax.get_legend().get_texts()) == sorted(set(frame.regime))
    scattered = frame.sample(frac=0.5, random_state=1)
    ax = plot.design_map(scattered, "shear2", "normal2", "stick_right")
    points = next(c for c in ax.collections if isinstance(c, PathCollection))
    assert np.array_equal(points.get_offsets(), scattered[["shear2", "normal2"]].to_numpy())


def test_design_map_of_crack_verdicts(design):
    # A crack sweep's verdict column (analysis = "crack") is drawn as categories, like the CLI's
    # --color crack.verdict; a failed row (its error column set) is grey, "no value".
    frame, shears, normals = design
    verdicts = np.where(frame.shear2 < 200.0, "no-growth",
                        np.where(frame.shear2 < 400.0, "arrests", "propagates"))
    error = np.where((frame.shear2 == 600.0) & (frame.normal2 == 1000.0), "failed", "")
    cracked = frame.assign(**{"crack.verdict": verdicts, "error": error})
    ax = plot.design_map(cracked, "shear2", "normal2", "crack.verdict")
    mesh = next(c for c in ax.collections if isinstance(c, QuadMesh))
    names = ["no-growth", "arrests", "propagates", ""]
    shown = np.where(error != "", "", verdicts)
    codes = np.array([names.index(v) for v in shown]).reshape(len(normals), len(shears))
    assert np.array_equal(np.asarray(mesh.get_array()).reshape(codes.shape), codes)
    legend = sorted(t.get_text() for t in ax.get_legend().get_texts())
    assert legend == ["arrests", "no value", "no-growth", "propagates"]
    assert ax.get_title() == "crack verdict"


def test_design_map_asks_for_where_when_more_columns_vary(design):
    frame, _, _ = design
    both = pd.concat([frame, frame.assign(friction=0.3)], ignore_index=True)
    with pytest.raises(ValueError, match=r"several rows share a point.*where=.*friction"):
        plot.design_map(both, "shear2", "normal2")
    ax = plot.design_map(both, "shear2", "normal2", "stick_right", where={"friction": 0.6})
    assert "friction coefficient f = 0.6000" in ax.get_title()
    with pytest.raises(ValueError, match="invalid where friction = 0.5"):
        plot.design_map(both, "shear2", "normal2", where={"friction": 0.5})
    with pytest.raises(ValueError, match="lacks column.*'cycle.point2.shear'"):
        plot.design_map(both, "cycle.point2.shear", "normal2")
    with pytest.raises(ValueError, match="invalid color 'error': it must be 'regime', 'crack.verdict'"):
        plot.design_map(frame, "shear2", "normal2", "error")


def test_figures_draw_on_the_axes_given(hertz, below):
    result, frame = hertz
    fig, axes = plt.subplots(1, 3)
    assert plot.load_space(result, frame, axes=axes[:2]) is fig
    xs, zs, stress = below
    assert plot.stress_map(stress, xs, zs, ax=axes[2]) is axes[2]
    with pytest.raises(ValueError, match="axes must be two Axes"):
        plot.load_space(result, axes=axes)


def test_without_matplotlib_the_module_imports_and_a_call_says_how_to_install(monkeypatch, hertz):
    code = "import sys; sys.modules['matplotlib'] = None; import halfplane.plot; print('ok')"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False)
    assert done.returncode == 0 and done.stdout.strip() == "ok", done.stderr
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)
    with pytest.raises(ImportError, match=r'pip install "./python\[plot\]"'):
        plot.load_space(hertz[0])


def test_crack_growth_draws_the_ranges_and_the_threshold_on_log_axes():
    result = halfplane.crack(
        halfplane.read_case(ROOT / "examples" / "crack.toml"),
        lengths={"from": 0.002, "to": 0.3, "count": 8},
        cells=200,
    )
    ax = plot.crack_growth(result)
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    lines = {line.get_label(): line for line in ax.get_lines()}
    rows = result.rows
    np.testing.assert_array_equal(lines["ΔK effective"].get_xdata(), rows["length"])
    np.testing.assert_array_equal(lines["ΔK effective"].get_ydata(), rows["delta_k_eff"])
    np.testing.assert_array_equal(
        lines["threshold ΔK_th(l) (El Haddad)"].get_ydata(), rows["threshold"]
    )
    assert lines["threshold ΔK_th(l) (El Haddad)"].get_linestyle() == "--"
    assert result.intensity_unit in ax.get_ylabel() and "mm" in ax.get_xlabel()
    assert result.verdict in ax.get_title()
    plt.close("all")


def test_fretting_loops_draw_each_checkpoints_loop():
    result = halfplane.wear(
        halfplane.read_case(ROOT / "examples" / "wear-sliding.toml"),
        cells=100,
        cycles=100,
        checkpoints=[1, 100],
    )
    ax = plot.fretting_loops(result)
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert set(lines) == {"cycle 1", "cycle 100"}
    loop = result.fretting_loop(100)
    np.testing.assert_array_equal(lines["cycle 100"].get_xdata(), loop["relative_displacement"])
    np.testing.assert_array_equal(lines["cycle 100"].get_ydata(), loop["shear"])
    assert "datum" in ax.get_xlabel() and "N/mm" in ax.get_ylabel()
    with pytest.raises(KeyError, match="cycle 2 is not a checkpoint"):
        plot.fretting_loops(result, cycles=[2])
    plt.close("all")

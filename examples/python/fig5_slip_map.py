"""The paper's Figure 5 from one steady_batch call: the slip zone at the right edge of the smaller
contact, over a0 = a(P0), against the shear range dQ/(f P0), for P2/P1 = 1, 1.2, 1.5 and
dsigma/P1 = 0, 0.02, 0.05 per mm, with f = 0.3 and 0.6 (Hertz, R = 50 mm, E = 200 GPa, nu = 0.3,
P1 = 1000 N/mm; the same map as `halfplane plot slip-map examples/hertz.toml`).

Each cycle runs from (P1, -dQ/2, dsigma/2) to (P2, dQ/2, -dsigma/2). Points the steady-state
analysis does not cover (slip reversing in a half, gross sliding) have an error and are left out,
which breaks the curves with tension before the full-stick limit.

Run: python examples/python/fig5_slip_map.py [-o FILE.png]  (default target/figure5-slip-map.png)
"""

from __future__ import annotations

import argparse
import os
import itertools

import numpy as np
import pandas as pd

import halfplane

P1 = 1000.0  # N/mm
FRICTIONS = [0.3, 0.6]
RATIOS = [1.0, 1.2, 1.5]  # P2/P1
TENSIONS = [0.0, 0.02, 0.05]  # dsigma/P1, 1/mm
X = np.arange(1, 60) / 60.0  # dQ/(f P0)


def slip_map() -> pd.DataFrame:
    """Every point of the map as one table row, solved in a single steady_batch call; adds x and
    y = (min(a1, a2) - n)/a0 (NaN where the analysis does not apply)."""
    grid = pd.DataFrame(
        list(itertools.product(FRICTIONS, RATIOS, TENSIONS, X)),
        columns=["friction", "ratio", "tension", "x"],
    )
    p2 = grid.ratio * P1
    dq = grid.x * grid.friction * 0.5 * (P1 + p2)
    dsigma = grid.tension * P1
    table = grid.assign(
        youngs_modulus=200_000.0, poisson_ratio=0.3, profile="hertz", radius=50.0,
        normal1=P1, shear1=-dq / 2, bulk1=dsigma / 2,
        normal2=p2, shear2=dq / 2, bulk2=-dsigma / 2,
    )
    out = halfplane.steady_batch(table)
    a1, a2 = out.half_width_1, out.half_width_2
    # Hertz: a^2 is proportional to P, so a0 = a((P1 + P2)/2) = sqrt((a1^2 + a2^2)/2).
    a0 = np.sqrt(0.5 * (a1**2 + a2**2))
    return grid.assign(y=(np.minimum(a1, a2) - out.stick_right) / a0, regime=out.regime, error=out.error)


def plot(points: pd.DataFrame, output: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(FRICTIONS), figsize=(10, 4.2), sharey=True)
    styles = {0.0: "-", 0.02: "--", 0.05: ":"}
    colours = {1.0: "tab:blue", 1.2: "tab:orange", 1.5: "tab:green"}
    for ax, f in zip(axes, FRICTIONS):
        for (ratio, tension), curve in points[points.friction == f].groupby(["ratio", "tension"]):
            ax.plot(curve.x, curve.y, styles[tension], color=colours[ratio],
                    label=f"P2/P1 = {ratio:g}, Δσ/P1 = {tension:g}/mm")
        ax.set_title(f"f = {f:g}")
        ax.set_xlabel("ΔQ / (f P0)")
        ax.set_xlim(0, 1)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("right slip zone at the smaller contact / a0")
    axes[-1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(output, dpi=120)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    # A scratch directory by default (target/, cargo's), so a run leaves the repository as it was.
    parser.add_argument("-o", "--output", default="target/figure5-slip-map.png")
    args = parser.parse_args()
    os.makedirs(os.path.dirname(args.output) or ".", exist_ok=True)
    points = slip_map()
    plot(points, args.output)
    print(f"wrote {args.output}: {len(points)} cycles, {int((points.error != '').sum())} outside the analysis")


if __name__ == "__main__":
    main()

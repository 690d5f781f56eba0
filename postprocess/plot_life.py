#!/usr/bin/python3
"""Plots `rollcheck life --json` output: the life ratios as a figure.

Top: each body's L10 life over the cylinder's (Lundberg-Palmgren, orthogonal
shear: the same at every load and for both criteria, docs/methods/life.md)
over the rolling energy, the band spanning the other modelling choices (load
rule, end margin), the line at the default choices (dynamic load, 5 %
margin). Below 1 the cylinder lives longer. Bottom: each body's L10 life with
its rounded rim ends over without them against the edge radius r_e / r1 at
each load (the grid's default cell); below about 0.54 (the ends' integral above
the interior's) the ends govern.

usage: plot_life.py LIFE.json OUT.png
"""
import itertools
import json
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

KEY = "lundberg_palmgren_orthogonal_shear"
DEFAULT = {"load_rule": "dynamic", "end_margin": "0.05"}


def load_key(load_n):
    """The integrals' key of a load, as `rollcheck life` writes it ({:.6g})."""
    return f"{load_n:.6g}"


def body_colour(data, body):
    """One colour per body in both panels."""
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    return colours[data["bodies"].index(body) % len(colours)]


def life_ratios(data, body, cylinder, load_n):
    """L10(body) / L10(cylinder) in every cell, None where either loop is incomplete."""
    e = data["constants"]["weibull_slope"]
    ia = data["integrals"][body][load_key(load_n)][KEY]
    ib = data["integrals"][cylinder][load_key(load_n)][KEY]
    return [None if a is None or b is None or a == 0 else (b / a) ** (1 / e) for a, b in zip(ia, ib)]


def draw_grid(ax, data):
    grid, order = data["grid"], data["grid_order"]
    cells = list(itertools.product(*[range(len(grid[name])) for name in order]))
    e_at = order.index("rolling_energy")
    energies = grid["rolling_energy"]
    cylinder = next(c["bodies"][1] for c in data["comparisons"] if c["name"].endswith("vs cylinder"))
    bodies = [b for b in data["bodies"] if b != cylinder]
    for body in bodies:
        r = life_ratios(data, body, cylinder, data["loads_n"][0])
        lo, hi, line = [], [], []
        for i in range(len(energies)):
            here = [r[j] for j, cell in enumerate(cells) if cell[e_at] == i and r[j] is not None]
            lo.append(min(here) if here else math.nan)
            hi.append(max(here) if here else math.nan)
            pick = [r[j] for j, cell in enumerate(cells) if cell[e_at] == i and
                    all(grid[n][cell[order.index(n)]] == v for n, v in DEFAULT.items())]
            line.append(pick[0] if pick and pick[0] is not None else math.nan)
        x = list(range(len(energies)))
        colour = body_colour(data, body)
        ax.fill_between(x, lo, hi, color=colour, alpha=0.15, linewidth=0)
        ax.plot(x, line, "o-", color=colour, label=body, markersize=3)
    ax.axhline(1.0, color="black", linestyle="--", linewidth=0.8)
    ax.set_yscale("log")
    ax.set_xticks(range(len(energies)))
    ax.set_xticklabels(["E = " + e for e in energies])
    ax.set_ylabel(f"L10 / L10 {cylinder}")
    ax.set_title("Lundberg-Palmgren life against the cylinder's (below 1: the cylinder lives longer)")
    ax.legend(fontsize=7, ncol=2, loc="best")


def draw_rims(ax, data):
    rims = data["rims"]
    styles = ["-", "--", ":"]
    loads = data["loads_n"]
    for k, body in enumerate(data["bodies"]):
        for l, load in enumerate(loads):
            life = next((x for x in rims["lives"] if x["body"] == body and x["load_n"] == load), None)
            if not life or not life["rows"]:
                continue
            ax.plot([r["edge_radius_over_radius"] for r in life["rows"]],
                    [r["life_with_over_without_ends"] for r in life["rows"]], styles[l % len(styles)],
                    color=body_colour(data, body), marker="o", markersize=2.5,
                    label=f"{body}, {load:.3g} N" if l == 0 or k == 0 else None)
    e = data["constants"]["weibull_slope"]
    ax.axhline(0.5 ** (1 / e), color="black", linestyle="--", linewidth=0.8)
    ax.axvline(rims["rim_study_edge_radius_over_radius"], color="grey", linewidth=0.8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("edge radius r_e / r1 (grey: the rim study's finish)")
    ax.set_ylabel("L10 with rim ends / without")
    ax.set_title("Rounded rim ends (" + ", ".join(f"{styles[i % 3]} {x:.3g} N" for i, x in enumerate(loads))
                 + "); above the dashed line the interior governs")
    ax.legend(fontsize=6, ncol=2, loc="best")


def draw(data, png):
    """The two panels of `data` into `png`."""
    fig, (grid_axes, rim_axes) = plt.subplots(2, 1, figsize=(9, 7.5), constrained_layout=True)
    draw_grid(grid_axes, data)
    draw_rims(rim_axes, data)
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    draw(json.loads(Path(argv[1]).read_text()), argv[2])


if __name__ == "__main__":
    main(sys.argv)

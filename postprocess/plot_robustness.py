#!/usr/bin/python3
"""Plots `rollcheck robustness --json` output: for each comparison of two
bodies, each score's ratio over the rolling energy, the band spanning every
other modelling choice (contact width, load rule, end margin) and the line at
the default choices (Hertz width, dynamic load, 5 % margin; static load under
a uniform rate, where no free motion exists). Below 1 the first body is the
more uniform. The family's ranking (its five best against the rest) has no
per-body values and is not drawn: its verdict is in the table.

usage: plot_robustness.py ROBUSTNESS.json OUT.png
"""
import itertools
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def cells(grid, order):
    """The cells in the order the values are stored: the last choice fastest."""
    return list(itertools.product(*[range(len(grid[name])) for name in order]))


def ratios(data, a, b, score):
    va, vb = data["values"][a][score], data["values"][b][score]
    out = []
    for x, y in zip(va, vb):
        if x is None or y is None or (x == 0 and y == 0):
            out.append(None)
        else:
            out.append(math.inf if y == 0 else x / y)
    return out


def draw(data, png, names=None):
    """Draws the comparisons of `data` (those named in `names`, else all) into `png`."""
    grid, order = data["grid"], data["grid_order"]
    energies = grid["rolling_energy"]
    all_cells = cells(grid, order)
    e_at = order.index("rolling_energy")
    default = {"contact_width": "hertz", "load_rule": "dynamic", "end_margin": "0.05"}
    pairs = []
    for c in data["comparisons"]:
        if (all(b in data["values"] for b in c["bodies"]) and (c["name"], tuple(c["bodies"])) not in pairs
                and (names is None or c["name"] in names)):
            pairs.append((c["name"], tuple(c["bodies"])))
    fig, axes = plt.subplots(len(pairs), 1, figsize=(9, 3.2 * len(pairs)), squeeze=False)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, (name, (a, b)) in zip(axes[:, 0], pairs):
        for k, score in enumerate(data["scores"]):
            r = ratios(data, a, b, score)
            lo, hi, line = [], [], []
            for i, energy in enumerate(energies):
                here = [r[j] for j, cell in enumerate(all_cells) if cell[e_at] == i and r[j] not in (None, math.inf)]
                lo.append(min(here) if here else math.nan)
                hi.append(max(here) if here else math.nan)
                want = dict(default, load_rule="static") if energy == "uniform_rate" else default
                pick = [r[j] for j, cell in enumerate(all_cells) if cell[e_at] == i and
                        all(grid[n][cell[order.index(n)]] == v for n, v in want.items())]
                line.append(pick[0] if pick and pick[0] not in (None, math.inf) else math.nan)
            x = list(range(len(energies)))
            colour = colours[k % len(colours)]
            ax.fill_between(x, lo, hi, color=colour, alpha=0.15, linewidth=0)
            ax.plot(x, line, "o-", color=colour, label=score, markersize=3)
        ax.axhline(1.0, color="black", linestyle="--", linewidth=0.8)
        ax.set_yscale("log")
        ax.set_xticks(range(len(energies)))
        ax.set_xticklabels(["E = " + e if e != "uniform_rate" else "uniform rate" for e in energies])
        ax.set_ylabel(f"{a} / {b}")
        ax.set_title(name + " (below 1: " + a + " more uniform)")
    axes[0, 0].legend(fontsize=7, ncol=2, loc="best")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    with open(argv[1]) as f:
        draw(json.load(f), argv[2])


if __name__ == "__main__":
    main(sys.argv)

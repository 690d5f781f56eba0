"""Where a roller family's optimum lies: the plot of one optimize run.

Reads OUT/optimize.json (written by `rollcheck optimize --out OUT` or
`rollcheck run cases/optimize_*.toml`) and draws into OUT:
  sweeps.png  the score along each parameter axis through the start (the
              others held there), the start's noise band (+- 2 sigma) and the
              points the search evaluated, projected onto each axis, with the
              optimum marked. Bodies whose score is infinite (FEM-SDS of a
              body that cannot roll a whole loop) are marked as crosses at
              the top of each panel.

    /usr/bin/python3 postprocess/plot_optimize.py --out OUT
"""
import argparse
import json
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def number(value):
    """A JSON number of rollcheck's convention ("inf" for infinity) as a float."""
    return float(value)


def finite_points(xs, ys):
    """The (x, y) pairs with a finite y, and the x of the others."""
    finite = [(x, y) for x, y in zip(xs, map(number, ys)) if y != float("inf")]
    return [p[0] for p in finite], [p[1] for p in finite], [x for x, y in zip(xs, map(number, ys)) if y == float("inf")]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="folder holding optimize.json; sweeps.png goes there")
    args = parser.parse_args()
    with open(os.path.join(args.out, "optimize.json")) as f:
        result = json.load(f)
    names = result["parameters"]
    sweeps = result["sweeps"]
    start, start_value = result["start"], result["start_value"]
    sigma = result["noise"]["sigma"]
    best = result["optimum"]
    history = result["search"]["history"]

    fig, axes = plt.subplots(1, max(len(sweeps), 1), figsize=(4 * max(len(sweeps), 1), 3.6), squeeze=False)
    for ax, sweep in zip(axes[0], sweeps):
        i = sweep["axis"]
        hx, hy, h_inf = finite_points([h["x"][i] for h in history], [h["value"] for h in history])
        ax.plot(hx, hy, ".", color="0.7", ms=4, label="search (all points, projected)")
        sx, sy, s_inf = finite_points(sweep["coordinates"], sweep["values"])
        ax.plot(sx, sy, "o-", color="C0", label="sweep through the start")
        if h_inf or s_inf:
            ax.plot(h_inf + s_inf, [1.0] * len(h_inf + s_inf), "x", color="C3", transform=ax.get_xaxis_transform(),
                    clip_on=False, label="infinite (no whole loop)")
        ax.axhspan(start_value - 2 * sigma, start_value + 2 * sigma, color="C0", alpha=0.12,
                   label="start +- 2 sigma noise")
        ax.plot([start[i]], [start_value], "s", color="C0", mfc="none", ms=9, label="start")
        ax.plot([best["x"][i]], [best["value"]], "*", color="C3", ms=12,
                label="optimum" + (" (beats the start)" if best["beats_start"] else " (within the noise)"))
        ax.set_xlabel(names[i])
        ax.set_ylabel(result["score"])
    axes[0][0].legend(fontsize=7)
    fig.suptitle(f"{result['score']} of the {result['family']} family, {result['oracle']} oracle, "
                 f"{result['mesh']['points_per_circle']} points per circle", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "sweeps.png"), dpi=120)
    print("sweeps.png: the score along each axis through the start, and the search's points")


if __name__ == "__main__":
    main()

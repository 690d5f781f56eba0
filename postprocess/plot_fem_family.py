"""FEM-SDS of a family: the plot of one `rollcheck search --score fem-sds` run.

Reads OUT/family.json and draws OUT/family.png: one panel per score
(the preprint's point-Hertz SDS, line-Hertz SDS, FEM-SDS, the uniformity U),
each body's ratio to the cylinder, the family ranked under that score
(log scale). Genomes are grey, the references coloured; bodies that could not
roll a whole loop are left out of the panels and listed in the title.

    /usr/bin/python3 postprocess/plot_fem_family.py --out OUT
"""
import os

import matplotlib
from out_folder import read_summary
matplotlib.use("Agg")
import matplotlib.pyplot as plt

SCORES = [("point_hertz_sds", "point-Hertz SDS (the preprint's)"), ("line_hertz_sds", "line-Hertz SDS"),
          ("fem_sds", "FEM-SDS"), ("uniformity", "uniformity U")]
COLOURS = {"paper (90, 1, 1)": "tab:blue", "oloid": "tab:green", "cylinder": "tab:red"}


def label(row):
    if row["kind"] == "genome":
        return f"({row['theta_deg']:g}, {row['offset']:g}, {row['ratio']:g})"
    return row["kind"]


def main():
    out, family = read_summary(__doc__, "family.json", "folder holding family.json; family.png goes there")
    rows = family["genomes"] + family["references"]
    scored = [r for r in rows if r["scored"] and "over_cylinder" in r]
    unscored = [label(r) for r in rows if not r["scored"]]
    fig, axes = plt.subplots(len(SCORES), 1, figsize=(12, 3.2 * len(SCORES)))
    for ax, (key, title) in zip(axes, SCORES):
        ranked = sorted((r for r in scored if r["over_cylinder"][key] is not None),
                        key=lambda r: r["over_cylinder"][key])
        values = [r["over_cylinder"][key] for r in ranked]
        colours = [COLOURS.get(r["kind"], "0.6") for r in ranked]
        ax.bar(range(len(ranked)), values, color=colours)
        ax.set_yscale("log")
        ax.axhline(1.0, color="tab:red", lw=0.8, ls="--")
        ax.set_xticks(range(len(ranked)))
        ax.set_xticklabels([label(r) for r in ranked], rotation=90, fontsize=6)
        ax.set_ylabel("/ cylinder")
        ax.set_title(f"{title}, ranked (lower is more even)", fontsize=10)
    note = f"; no whole loop: {', '.join(unscored)}" if unscored else ""
    fig.suptitle(f"the family over one loop of real rolling each: {len(scored)} bodies scored{note}", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "family.png"), dpi=110)


if __name__ == "__main__":
    main()

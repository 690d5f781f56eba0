"""The pressure near a rim: the plot of one `rollcheck rim --json RIM.json` run.

Draws the centre-line pressure p(x, y = 0) over the last 3 b of the ruling,
one curve per edge mesh level, in units of the far side's pressure and of
line Hertz's half-width b, with the edge (or where the fillet leaves the
sheet) marked. A singular edge shows its pressure rising with every level; a
converged end shows the curves on top of each other. Writes OUT (a .png),
whole or not at all.

    /usr/bin/python3 postprocess/plot_rim.py RIM.json OUT.png
"""
import argparse
import json
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("json", help="rollcheck rim --json output")
    parser.add_argument("png", help="the plot to write")
    args = parser.parse_args()
    with open(args.json) as f:
        rim = json.load(f)
    b = rim["half_width_m"]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for level in rim["levels"]:
        points = sorted(level["centre_line_x_m_pressure_pa"])
        ax.plot([x / b for x, _ in points], [p / level["far_peak_pa"] for _, p in points], marker=".",
                markersize=3, linewidth=1, label=f"h_e = b / {b / level['edge_element_m']:.0f}")
    ax.axvline(-rim["fillet_start_m"] / b, color="grey", linestyle=":", label="edge" if rim["edge_radius_m"] == 0
               else "fillet starts")
    # From 3 b before the sheet ends; beyond the edge lies the other face, out of contact.
    ax.set_xlim(-3 - rim["fillet_start_m"] / b, 0.5)
    ax.set_xlabel("x / b along the ruling (the edge at 0)")
    ax.set_ylabel("p / interior pressure (centre line)")
    ax.set_title(f"{rim['interior_angle_deg']:.1f} deg rim, edge radius {rim['edge_radius_m'] / b:.2g} b, "
                 f"{rim['counter_face']} counter-face\n{rim['verdict']}", fontsize=8)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    partial = args.png + ".partial.png"
    fig.savefig(partial, dpi=120)
    os.replace(partial, args.png)
    print(f"{args.png}: the centre-line pressure near the rim, {len(rim['levels'])} levels")


if __name__ == "__main__":
    main()

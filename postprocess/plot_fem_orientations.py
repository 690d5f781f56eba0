"""FEM contact stress at sampled orientations: the plots of one fem-sds run.

Reads OUT/fem_sds.json (written by `rollcheck fem-sds --out OUT` or
`rollcheck run cases/fem_sds_*.toml`) and draws into OUT:
  peaks.png     per orientation, the FEM peak pressure (plane-strain slices,
                away from the creases) at both mesh levels against the
                line-contact Hertz peak and the preprint's point-Hertz peak
                (log scale: they differ by an order of magnitude);
  profiles.png  the pressure along the contact ruling: FEM slice peaks
                (markers) and line-Hertz p0(s) (lines), one colour per orientation.

    /usr/bin/python3 postprocess/plot_fem_orientations.py --out OUT
"""
import os

import matplotlib
from out_folder import read_summary
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    out, summary = read_summary(__doc__, "fem_sds.json", "folder holding fem_sds.json; the PNGs go there")
    rows = summary["per_orientation"]
    solved = [r for r in rows if r["fem_solved"]]
    title = f"{summary['body']}: {summary['source']}"

    fig, ax = plt.subplots(figsize=(8, 4.5))
    index = [r["index"] for r in rows]
    ax.semilogy(index, [r["point_hertz_peak_pa"] / 1e6 for r in rows], "s", mfc="none",
                label="preprint point-Hertz, max over its faces")
    ax.semilogy([r["index"] for r in solved], [r["line_hertz_peak_pa"] / 1e6 for r in solved], "o", mfc="none",
                ms=9, label="line-contact Hertz (slices)")
    ax.semilogy([r["index"] for r in solved], [r["fem_peak_pa"] / 1e6 for r in solved], "x",
                label="FEM plane-strain slices")
    ax.semilogy([r["index"] for r in solved], [r["fem_peak_refined_pa"] / 1e6 for r in solved], "+", ms=10,
                label="FEM, one level finer")
    for r in rows:
        if r["reaches_crease"]:
            ax.axvspan(r["index"] - 0.4, r["index"] + 0.4, color="0.92", zorder=0)
    ax.set_xlabel("sampled orientation (shaded: the contact reaches a crease; FEM peaks are taken away from it)")
    ax.set_ylabel("peak contact pressure (MPa)")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "peaks.png"), dpi=120)
    print("peaks.png: FEM against analytic peak pressure per orientation")

    if solved:
        fig, ax = plt.subplots(figsize=(8, 4.5))
        for k, r in enumerate(solved):
            colour = f"C{k % 10}"
            s = [x["position_m"] for x in r["slices"]]
            ax.plot(s, [x["line_hertz_peak_pa"] / 1e6 for x in r["slices"]], "-", color=colour, lw=1)
            ax.plot(s, [x["fem_peak_pa"] / 1e6 for x in r["slices"]], "x", color=colour,
                    label=f"#{r['index']} (c = {r['centre_of_pressure']:.2f})")
        ax.set_xlabel("position along the contact ruling (m)")
        ax.set_ylabel("peak pressure of the slice (MPa)")
        ax.set_title(f"{title}\nlines: line-contact Hertz; markers: FEM", fontsize=9)
        ax.legend(fontsize=7, ncol=2)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "profiles.png"), dpi=120)
        print("profiles.png: pressure along the contact ruling")


if __name__ == "__main__":
    main()

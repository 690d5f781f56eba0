"""Speed against error of the FEM models.

For every FEM case with a wall time (wall_s) and relative errors against
Hertz theory (p0_error, and a_error or b_error), draws the absolute error
against the wall time, log-log, one series per model and element degree
(the summary's model and degree), points joined in order of wall time.

    /usr/bin/python3 postprocess/plot_fem_speed_error.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from rollcheck_store import Skip, is_number, run_standalone

TITLE = "Speed against error of the FEM models"
QUANTITIES = (("p0_error", "peak pressure p0"), ("size_error", "contact size a or b"))


def point(case):
    s = case.summary
    if not is_number(s.get("wall_s")) or not is_number(s.get("p0_error")):
        return None
    size = s.get("a_error", s.get("b_error"))
    if not is_number(size):
        return None
    model = s.get("model", case.parameters.get("model", case.kind))
    degree = s.get("degree", case.parameters.get("degree", ""))
    return f"{model} P{degree}", s["wall_s"], {"p0_error": abs(s["p0_error"]), "size_error": abs(size)}, s.get("dofs")


def draw(cases, out_dir):
    series = {}
    for case in cases:
        p = point(case) if case.ok else None
        if p:
            series.setdefault(p[0], []).append(p[1:])
    if not series:
        raise Skip("no FEM case with wall_s, p0_error and a_error or b_error (the hertz scene writes them)")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), sharex=True)
    for ax, (key, name) in zip(axes, QUANTITIES):
        for model, points in sorted(series.items()):
            points.sort(key=lambda t: t[0])
            t = np.array([q[0] for q in points])
            e = np.array([max(q[1][key], 1e-12) for q in points])
            ax.loglog(t, e, "o-", label=model)
            for (wall, _, dofs), err in zip(points, e):
                if dofs:
                    ax.annotate(f"{dofs}", (wall, err), fontsize=6, xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel(f"|relative error| of {name}")
        ax.set_title(name, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"{TITLE} (labels: DOFs)")
    fig.tight_layout()
    png = "fem_speed_error.png"
    fig.savefig(f"{out_dir}/{png}", dpi=120)
    plt.close(fig)
    n = sum(len(v) for v in series.values())
    return [(png, f"{TITLE}: {n} FEM case(s) in {len(series)} model/degree series; errors against Hertz theory.")]


if __name__ == "__main__":
    run_standalone(draw)

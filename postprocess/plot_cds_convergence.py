"""CDS against samples (convergence).

For every successful case of scene kind "oracle" run with the rigid-body or
approximate oracle (summary written by study::to_json(BodyScores): "oracle",
"body", "convergence"), draws, log-log, the contact distribution score after
each snapshot of the samples: "convergence"/"cds", rows [samples, cds]. A
case without CDS snapshots (convergence_every = 0, or metrics without cds) is
named in the caption. The rolling oracle scores with U, not CDS, and is left
out. A dashed line of slope -1 marks O(1/T): a score that still falls that
way is dominated by sampling noise; one that levels off has converged to the
body's own non-uniformity. A key missing from an oracle summary is an error
naming it and the case.

    /usr/bin/python3 postprocess/plot_cds_convergence.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib import ticker
import numpy as np

from rollcheck_store import Figure, Skip, count, label, require, run_standalone

TITLE = "CDS against samples (convergence)"
KIND = "oracle"


def snapshots(case):
    """(samples, cds) of an oracle case's CDS snapshots; None when it has none."""
    where = f"case {case.name} ({KIND} summary)"
    convergence = require(case.summary, "convergence", where)
    if "cds" not in convergence:
        return None
    rows = np.asarray(convergence["cds"], dtype=float)
    if rows.ndim != 2 or rows.shape[1] != 2 or len(rows) < 2:
        return None
    return rows[:, 0], rows[:, 1]


def tail_slope(samples, cds):
    """Log-log slope of CDS against samples over the last half of the snapshots."""
    half = slice(len(samples) // 2, None)
    keep = (samples[half] > 0) & (cds[half] > 0) & np.isfinite(cds[half])
    if keep.sum() < 2:
        return float("nan")
    return np.polyfit(np.log(samples[half][keep]), np.log(cds[half][keep]), 1)[0]


def draw(cases, out_dir):
    scored = [c for c in cases if c.ok and c.kind == KIND
              and require(c.summary, "oracle", f"case {c.name} ({KIND} summary)") != "rolling"]
    curves = [(c, s) for c in scored for s in [snapshots(c)] if s is not None]
    without = [c.name for c in scored if all(c is not d for d, _ in curves)]
    if not curves:
        raise Skip("no successful rigid or approximate oracle case with CDS snapshots (an oracle case with "
                   "metrics including cds and convergence_every > 0)"
                   + (f"; without snapshots: {', '.join(without)}" if without else ""))
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for case, (samples, cds) in curves:
        ax.loglog(samples, cds, "o-", ms=3, label=label(case, ("body", "oracle")))
    x0, y0 = curves[0][1][0][0], curves[0][1][1][0]
    xs = np.array([min(s.min() for _, (s, _) in curves), max(s.max() for _, (s, _) in curves)])
    ax.loglog(xs, y0 * x0 / xs, "k--", lw=1, label="slope -1: O(1/T)")
    ax.set_xlabel("samples T")
    ax.set_ylabel("CDS (contact distribution score)")
    ax.set_title(TITLE)
    ax.grid(True, which="both", alpha=0.3)
    # Labels at 1, 2 and 5 of each decade: an axis spanning less than a decade still reads.
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(ticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
        axis.set_major_formatter(ticker.FuncFormatter(lambda value, _: f"{value:.3g}"))
        axis.set_minor_formatter(ticker.NullFormatter())
    ax.legend(fontsize=7)
    fig.tight_layout()
    png = "cds_convergence.png"
    fig.savefig(f"{out_dir}/{png}", dpi=120)
    plt.close(fig)
    shows = (f"The contact distribution score after each snapshot of the samples, log-log, for "
             f"{count(len(curves), 'oracle case')}, with a line of slope -1 (O(1/T), pure sampling noise).")
    parts = [f"{c.name}: CDS {cds[-1]:.3g} after {samples[-1]:.0f} samples, slope {tail_slope(samples, cds):.2f} "
             f"over the last half of the snapshots" for c, (samples, cds) in curves]
    conclusion = ("; ".join(parts) + ". A slope near -1 means the score is still mostly sampling noise (more "
                  "samples would lower it); near 0, it has settled at the body's own non-uniformity.")
    if without:
        conclusion += f" Not drawn, no CDS snapshots: {', '.join(without)}."
    return [Figure(png, TITLE, shows, conclusion)]


if __name__ == "__main__":
    run_standalone(draw)

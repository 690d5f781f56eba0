"""CDS against samples (convergence).

Draws, log-log, the contact distribution score after each snapshot of the
samples, for every case whose summary holds convergence snapshots: an array
with rows [samples, cds] named "convergence" or named with "cds" under such a
key (convergence/cds; the other scores' snapshots are left out), or an object
under such a key with a samples array (key containing "sample" or "step")
and a score array (key containing "cds" or "score"). Without snapshots, it
draws CDS against n_samples over cases of one body that differ in their
sample counts. A dashed line of slope -1 marks O(1/T) convergence.

    /usr/bin/python3 postprocess/plot_cds_convergence.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from rollcheck_store import Skip, arrays, is_number, label, run_standalone, subtrees

TITLE = "CDS against samples (convergence)"


def snapshot_series(case):
    """(samples, cds, name) of every convergence snapshot series in a case."""
    for path, a in arrays(case.summary, ndim=2):
        leaf = path.split("/")[-1].lower()
        if "convergence" in path.lower() and (leaf == "convergence" or "cds" in leaf) and a.shape[1] == 2 \
                and len(a) > 1:
            yield a[:, 0], a[:, 1], path
    for path, node in subtrees(case.summary, "convergence"):
        one_d = {k: np.asarray(v) for k, v in node.items()
                 if isinstance(v, np.ndarray) and v.ndim == 1 and len(v) > 1}
        x = next((v for k, v in one_d.items() if "sample" in k.lower() or "step" in k.lower()), None)
        y = next((v for k, v in one_d.items() if "cds" in k.lower() or "score" in k.lower()), None)
        if x is not None and y is not None and len(x) == len(y):
            yield x, y, path


def across_cases(cases):
    """CDS against n_samples over cases of one body: {label: (samples, cds)} with >= 2 points."""
    groups = {}
    for c in cases:
        s = c.summary
        if is_number(s.get("cds")) and is_number(s.get("n_samples")):
            key = (c.kind, c.parameters.get("body", ""), c.parameters.get("oracle", ""))
            groups.setdefault(key, []).append((s["n_samples"], s["cds"]))
    out = {}
    for (kind, body, oracle), points in groups.items():
        if len({p[0] for p in points}) >= 2:
            points.sort()
            out[f"{body or kind} {oracle}".strip()] = tuple(np.array(v) for v in zip(*points))
    return out


def draw(cases, out_dir):
    curves = [(x, y, f"{label(c)}: {name}") for c in cases if c.ok for x, y, name in snapshot_series(c)]
    if not curves:
        curves = [(x, y, name) for name, (x, y) in across_cases([c for c in cases if c.ok]).items()]
    curves = [(x, y, n) for x, y, n in curves if np.all(x > 0) and np.all(y > 0)]
    if not curves:
        raise Skip("no case holds CDS convergence snapshots (a summary key 'convergence' with rows "
                   "[samples, cds]), nor several oracle cases of one body at different sample counts")
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for x, y, name in curves:
        ax.loglog(x, y, "o-", ms=3, label=name)
    x0, y0 = curves[0][0][0], curves[0][1][0]
    xs = np.array([min(c[0].min() for c in curves), max(c[0].max() for c in curves)])
    ax.loglog(xs, y0 * x0 / xs, "k--", lw=1, label="slope -1: O(1/T)")
    ax.set_xlabel("samples")
    ax.set_ylabel("CDS (contact distribution score)")
    ax.set_title(TITLE)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    png = "cds_convergence.png"
    fig.savefig(f"{out_dir}/{png}", dpi=120)
    plt.close(fig)
    return [(png, f"{TITLE}: {len(curves)} series.")]


if __name__ == "__main__":
    run_standalone(draw)

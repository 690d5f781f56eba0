"""FEM against analytic SDS.

For every case whose summary has both a FEM stress distribution score (a
number under a key containing "fem_sds") and the analytic one (a key
"sds", "analytic_sds" or "hertz_sds"), draws both per case as bars, log
scale. If the summary also holds per-orientation peak pressures, FEM (a key
containing "fem" and "peak") against analytic (a key containing "peak" and
"hertz" or "analytic"), a second panel plots one against the other with the
line of equality.

    /usr/bin/python3 postprocess/plot_fem_sds.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from rollcheck_store import Skip, arrays, is_number, label, run_standalone, walk

TITLE = "FEM against analytic SDS"


def scores(case):
    """(fem_sds, analytic_sds) of a case, or None."""
    leaves = {path.split("/")[-1].lower(): v for path, v in walk(case.summary) if is_number(v)}
    fem = next((v for k, v in leaves.items() if "fem_sds" in k), None)
    analytic = next((leaves[k] for k in ("analytic_sds", "hertz_sds", "sds") if k in leaves), None)
    return (fem, analytic) if fem is not None and analytic is not None else None


def peaks(case):
    """(fem, analytic) per-orientation peak pressures of a case, or None."""
    one_d = [(p.split("/")[-1].lower(), a) for p, a in arrays(case.summary, ndim=1)]
    fem = next((a for k, a in one_d if "fem" in k and "peak" in k), None)
    analytic = next((a for k, a in one_d if "peak" in k and ("hertz" in k or "analytic" in k) and "fem" not in k),
                    None)
    if fem is None or analytic is None or len(fem) != len(analytic):
        return None
    return fem, analytic


def draw(cases, out_dir):
    rows = [(c, s) for c in cases if c.ok for s in [scores(c)] if s]
    if not rows:
        raise Skip("no case holds both a FEM SDS (key with 'fem_sds') and an analytic SDS ('sds', "
                   "'analytic_sds' or 'hertz_sds'): the FEM-SDS scene (issue 5) writes them")
    pairs = [(c, p) for c, _ in rows for p in [peaks(c)] if p]
    fig, axes = plt.subplots(1, 2 if pairs else 1, figsize=(12 if pairs else 7, 5), squeeze=False)
    ax = axes[0][0]
    x = np.arange(len(rows))
    ax.bar(x - 0.2, [s[1] for _, s in rows], 0.4, label="analytic SDS (point Hertz)")
    ax.bar(x + 0.2, [s[0] for _, s in rows], 0.4, label="FEM SDS")
    ax.set_xticks(x, [label(c, ("body",)) for c, _ in rows], rotation=20, ha="right", fontsize=8)
    ax.set_yscale("log")
    ax.set_ylabel("SDS")
    ax.set_title("SDS per case", fontsize=10)
    ax.legend(fontsize=8)
    if pairs:
        ax = axes[0][1]
        for case, (fem, analytic) in pairs:
            ax.loglog(analytic, fem, "o", ms=4, label=label(case, ("body",)))
        lo = min(min(a.min(), f.min()) for _, (f, a) in pairs)
        hi = max(max(a.max(), f.max()) for _, (f, a) in pairs)
        ax.loglog([lo, hi], [lo, hi], "k--", lw=1, label="equal")
        ax.set_xlabel("analytic peak pressure [Pa]")
        ax.set_ylabel("FEM peak pressure [Pa]")
        ax.set_title("peak pressure per sampled orientation", fontsize=10)
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(TITLE)
    fig.tight_layout()
    png = "fem_sds.png"
    fig.savefig(f"{out_dir}/{png}", dpi=120)
    plt.close(fig)
    return [(png, f"{TITLE}: {len(rows)} case(s).")]


if __name__ == "__main__":
    run_standalone(draw)

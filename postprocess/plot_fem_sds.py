"""FEM against analytic SDS.

For every successful case of scene kind "fem-sds" (summary written by
study::to_json(FemSdsResult)), draws its stress distribution scores as bars,
log scale, each over every sample of one rolling loop ("samples", with its
convergence in "fem_sds_status"): the preprint's analytic one ("analytic_sds",
point Hertz), the line-contact Hertz one ("line_hertz_sds") and the FEM one
("fem_sds"); a
score that is null (nothing solved) or "inf" (no distribution) has no bar and
is named in the caption. A second panel plots, per orientation solved
directly slice by slice ("per_orientation", "fem_solved"), the FEM peak pressure ("fem_peak_pa")
against the preprint's point-Hertz peak ("point_hertz_peak_pa") and the
line-contact Hertz peak ("line_hertz_peak_pa"), with the line of equality.
A key missing from a fem-sds summary is an error naming it and the case.

    /usr/bin/python3 postprocess/plot_fem_sds.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from rollcheck_store import Figure, Skip, count, is_number, percent, require, run_standalone

TITLE = "FEM against analytic SDS"
KIND = "fem-sds"
SCORES = (("analytic_sds", "analytic SDS (preprint, point Hertz)"), ("line_hertz_sds", "line-contact Hertz SDS"),
          ("fem_sds", "FEM SDS"))


def where(case):
    return f"case {case.name} ({KIND} summary)"


def scores(case):
    """{key: score or None} of a fem-sds case; None for a score without a number (null or "inf")."""
    return {key: (v if is_number(v) else None)
            for key, _ in SCORES for v in [require(case.summary, key, where(case))]}


def peaks(case):
    """(fem, point-Hertz, line-Hertz) peak pressures of the solved orientations of a fem-sds case."""
    rows = require(case.summary, "per_orientation", where(case))
    columns = ([], [], [])
    for k, row in enumerate(rows):
        at = f"{where(case)}: per_orientation/{k}"
        if require(row, "fem_solved", at):
            for column, key in zip(columns, ("fem_peak_pa", "point_hertz_peak_pa", "line_hertz_peak_pa")):
                column.append(require(row, key, at))
    return tuple(np.asarray(c, dtype=float) for c in columns), len(rows)


def body(case):
    return require(case.summary, "body", where(case))


def ratio(a, b):
    return f"{a / b:.3g}" if a is not None and b else "-"


def table(cases):
    """The numbers of the FEM-SDS section: a header and one row per fem-sds case."""
    header = ["case", "body", "loop samples", "analytic SDS", "line-Hertz SDS", "FEM SDS", "FEM / analytic",
              "FEM / line-Hertz", "FEM SDS status", "orientations solved directly"]
    rows = []
    for case in cases:
        if case.ok and case.kind == KIND:
            s = scores(case)
            (fem, _, _), n = peaks(case)
            rows.append([case.name, body(case), require(case.summary, "samples", where(case)),
                         *(f"{s[key]:.4g}" if s[key] is not None else "-" for key, _ in SCORES),
                         ratio(s["fem_sds"], s["analytic_sds"]), ratio(s["fem_sds"], s["line_hertz_sds"]),
                         require(case.summary, "fem_sds_status", where(case)), f"{len(fem)} of {n}"])
    return header, rows


def conclusion(case, s, fem, point, line, n):
    if not len(fem):
        return f"{case.name} ({body(case)}): none of its {n} orientations was solved by the FEM."
    to_line = np.abs(fem / line - 1)
    low, high = (point / fem).min(), (point / fem).max()
    return (f"{case.name} ({body(case)}): the FEM peak is within {percent(to_line.max())} of line-contact Hertz at "
            f"every one of its {len(fem)} solved orientations (of {n}), while the preprint's point-Hertz peak is "
            f"{low:.2g} to {high:.2g} times the FEM peak; FEM SDS / analytic SDS = "
            f"{ratio(s['fem_sds'], s['analytic_sds'])}, FEM SDS / line-Hertz SDS = "
            f"{ratio(s['fem_sds'], s['line_hertz_sds'])}.")


def draw_scores(ax, rows):
    x = np.arange(len(rows))
    width = 0.8 / len(SCORES)
    numbers = [s[key] for _, s in rows for key, _ in SCORES if s[key] is not None]
    top, least = max(numbers, default=1.0), min(numbers, default=1.0)
    # A log axis has no zero: every bar starts a decade below the least score, so none is cut by the axis.
    floor = least / 10
    for k, (key, name) in enumerate(SCORES):
        values = np.array([s[key] if s[key] is not None else floor for _, s in rows])
        bars = ax.bar(x + (k - 1) * width, values - floor, width, bottom=floor, label=name)
        ax.bar_label(bars, labels=[f"{s[key]:.3g}" if s[key] is not None else "-" for _, s in rows], fontsize=7)
    ax.set_xticks(x, [f"{c.name}\n({body(c)})" for c, _ in rows], fontsize=8)
    ax.set_yscale("log")
    ax.set_ylim(floor, 30 * top)  # room for the legend above the bars
    ax.set_ylabel("SDS")
    ax.set_title("stress distribution score per case", fontsize=10)
    ax.legend(fontsize=8, loc="upper left")


def draw_peaks(ax, pairs):
    for k, (case, (fem, point, line)) in enumerate(pairs):
        colour = f"C{k % 10}"
        ax.loglog(point, fem, "s", mfc="none", color=colour, ms=5, label=f"{body(case)}: against point Hertz")
        ax.loglog(line, fem, "o", color=colour, ms=4, label=f"{body(case)}: against line Hertz")
    values = np.concatenate([np.concatenate(p) for _, p in pairs])
    lo, hi = values[values > 0].min(), values.max()
    ax.loglog([lo, hi], [lo, hi], "k--", lw=1, label="equal")
    # Margins on both axes: no marker sits on the frame.
    ax.set_xlim(lo / 1.6, hi * 1.6)
    ax.set_ylim(lo / 1.6, hi * 1.6)
    ax.set_xlabel("analytic peak pressure [Pa]")
    ax.set_ylabel("FEM peak pressure [Pa]")
    ax.set_title("peak pressure per solved orientation", fontsize=10)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)


def draw(cases, out_dir):
    fem_cases = [c for c in cases if c.ok and c.kind == KIND]
    if not fem_cases:
        raise Skip(f"no successful case of kind '{KIND}' (a [scene] kind = \"{KIND}\" case file, e.g. "
                   f"cases/default/fem_sds_oloid.toml)")
    rows = [(c, scores(c)) for c in fem_cases]
    solved = [(c, *peaks(c)) for c in fem_cases]
    pairs = [(c, p) for c, p, _ in solved if len(p[0])]
    fig, axes = plt.subplots(1, 2 if pairs else 1, figsize=(12 if pairs else 7, 5), squeeze=False)
    draw_scores(axes[0][0], rows)
    if pairs:
        draw_peaks(axes[0][1], pairs)
    fig.suptitle(TITLE)
    fig.tight_layout()
    png = "fem_sds.png"
    fig.savefig(f"{out_dir}/{png}", dpi=120)
    plt.close(fig)
    bodies = sorted({body(c) for c in fem_cases})
    shows = (f"Left: the stress distribution score of {count(len(fem_cases), KIND + ' case')} on "
             f"{count(len(bodies), 'body', 'bodies')} ({', '.join(bodies)}): analytic (point Hertz, as in the "
             f"preprint), line-contact Hertz and FEM, log scale. Right: the FEM peak pressure of each solved "
             f"orientation against both analytic peaks.")
    text = " ".join(conclusion(c, s, *p, n) for (c, s), (_, p, n) in zip(rows, solved))
    without = [f"{c.name} ({name})" for c, s in rows for key, name in SCORES if s[key] is None]
    if without:
        text += f" No score (null or inf), no bar: {', '.join(without)}."
    return [Figure(png, TITLE, shows, text)]


if __name__ == "__main__":
    run_standalone(draw)

"""The report's headline figure: the cylinder / oloid ratio of each score in
each setting (findings.py), log scale, one band per setting and one line per
score in it. A recomputed value is a dot, the preprint's printed value a
ring on the same line; a range over the modelling choices (the robustness
study) a bar from its least to its largest ratio. Right of the line at 1 the
oloid's distribution is the more even, as the preprint claims; left of it
the cylinder's. Sized to fit the report's first screen beside its opening
paragraph.
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from findings import SETTINGS
from rollcheck_store import Figure, Skip

TITLE = "The oloid against the cylinder: cylinder / oloid ratio of each score"
PNG = "headline.png"
PRINTED = ", as printed"


def lines(rows):
    """Per setting (in SETTINGS' order), its lines: (score, low, high, printed value or None)."""
    out = []
    for setting in SETTINGS:
        here = [r for r in rows if r[0] == setting]
        printed = {r[1][:-len(PRINTED)]: r[2] for r in here if r[1].endswith(PRINTED)}
        scored = [(r[1], r[2], r[3], printed.pop(r[1], None)) for r in here if not r[1].endswith(PRINTED)]
        scored += [(score, None, None, value) for score, value in printed.items()]
        if scored:
            out.append((setting, scored))
    return out


def draw(rows, out_dir):
    if not rows:
        raise Skip("neither the audit's nor the robustness study's JSON was given")
    bands = lines(rows)
    fig, ax = plt.subplots(figsize=(10, 3.9))
    y, centres = 0.0, []
    for k, (setting, scored) in enumerate(bands):
        colour = f"C{SETTINGS.index(setting)}"
        top = y
        for score, low, high, printed in scored:
            if printed is not None:
                ax.plot(printed, y, "o", mfc="none", mec=colour, ms=7)
            if low is not None and low == high:
                ax.plot(low, y, "o", color=colour, ms=5)
            elif low is not None:
                ax.plot([low, high], [y, y], "-", color=colour, lw=5, solid_capstyle="butt", alpha=0.85)
            text = f"{score} " + (f"{low:.3g}x" if low == high else f"{low:.3g}-{high:.3g}x") if low is not None \
                else f"{score} {printed:.3g}x"
            if printed is not None and low is not None:
                text += f" (printed {printed:.3g}x)"
            right = max(v for v in (high, printed) if v is not None)
            ax.annotate(text, (right, y), xytext=(8, 0), textcoords="offset points", fontsize=7, va="center")
            y -= 1
        centres.append((top + y + 1) / 2)
        if k + 1 < len(bands):
            ax.axhline(y + 0.25, color="0.85", lw=0.8)
        y -= 0.5
    values = [v for r in rows for v in r[2:4]]
    ax.set_xscale("log")
    ax.set_xlim(min(values) / 3, max(values) * 60)   # room for the labels right of the largest
    ax.set_ylim(y + 0.5, 1.0)
    ax.set_yticks(centres, [setting for setting, _ in bands], fontsize=8)
    ax.axvline(1, color="k", lw=1)
    ax.text(1.15, 0.75, "oloid more even ->", fontsize=7, va="center")
    ax.text(0.87, 0.75, "<- cylinder more even", fontsize=7, va="center", ha="right")
    ax.set_xlabel("cylinder score / oloid score (log scale)", fontsize=8)
    ax.tick_params(axis="x", labelsize=8)
    ax.set_title(TITLE, fontsize=10)
    ax.grid(True, axis="x", alpha=0.3)
    fig.tight_layout()
    fig.savefig(f"{out_dir}/{PNG}", dpi=100)
    plt.close(fig)
    shows = ("One band per setting, one line per score: the audit's recomputations are dots (rings: the "
             "preprint's printed values), the robustness study's ranges over the modelling choices are bars.")
    return Figure(PNG, TITLE, shows, "")

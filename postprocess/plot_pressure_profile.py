"""Hertz pressure profile: FEM against analytic.

For every case whose summary has a profile (an object under a key
containing "profile" with a coordinate array ending in "_m" and a pressure
array ending in "_pa"), draws the FEM contact pressure along the surface
against Hertz theory, both scaled by the Hertz values: x / c_H and p / p0_H,
with c_H the contact radius a (point contact) or half-width b (line contact),
from the summary's a_hertz_m or b_hertz_m, and p0_H from p0_hertz_pa. In
these units every Hertz profile is the same ellipse, p / p0 = sqrt(1 - (x/c)^2).
The lower panel shows FEM minus Hertz, in units of p0_H.

    /usr/bin/python3 postprocess/plot_pressure_profile.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from rollcheck_store import Skip, is_number, label, run_standalone, subtrees

TITLE = "Hertz pressure profile: FEM against analytic"


def profile(case):
    """(x / c_H, p / p0_H, contact letter) of a case's FEM profile, or None."""
    s = case.summary
    letter = "a" if is_number(s.get("a_hertz_m")) else "b" if is_number(s.get("b_hertz_m")) else None
    if letter is None or not is_number(s.get("p0_hertz_pa")):
        return None
    for _, node in subtrees(s, "profile"):
        coords = [v for k, v in node.items() if k.endswith("_m") and isinstance(v, np.ndarray) and v.ndim == 1]
        fem = [v for k, v in node.items() if k.endswith("_pa") and "hertz" not in k and "analytic" not in k
               and isinstance(v, np.ndarray) and v.ndim == 1]
        if coords and fem and len(coords[0]) == len(fem[0]) and len(fem[0]) > 1:
            order = np.argsort(coords[0])
            return (coords[0][order] / s[f"{letter}_hertz_m"], fem[0][order] / s["p0_hertz_pa"], letter)
    return None


def draw(cases, out_dir):
    curves = [(c, p) for c in cases if c.ok for p in [profile(c)] if p is not None]
    if not curves:
        raise Skip("no case holds a FEM pressure profile (a summary object 'profile' with r_m or x_m and p_pa, "
                   "beside a_hertz_m or b_hertz_m and p0_hertz_pa: the hertz scene writes them)")
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 7), sharex=True, gridspec_kw={"height_ratios": [3, 1.3]})
    x_max = max(1.5, min(3.0, max(x.max() for _, (x, _, _) in curves)))
    xs = np.linspace(0, x_max, 600)
    top.plot(xs, np.sqrt(np.clip(1 - xs ** 2, 0, None)), "k-", lw=2, label="Hertz: sqrt(1 - (x/c)^2)")
    for case, (x, p, letter) in curves:
        keep = x <= x_max
        line, = top.plot(x[keep], p[keep], ".-", ms=3, lw=0.8, label=f"FEM {label(case)}, c = {letter}")
        hertz = np.sqrt(np.clip(1 - x[keep] ** 2, 0, None))
        bottom.plot(x[keep], p[keep] - hertz, ".-", ms=3, lw=0.8, color=line.get_color())
    top.set_ylabel("p / p0 (Hertz)")
    top.set_title(TITLE)
    top.grid(True, alpha=0.3)
    top.legend(fontsize=7)
    bottom.axhline(0, color="k", lw=1)
    bottom.set_xlabel("distance from the first point of contact / Hertz contact size c (a or b)")
    bottom.set_ylabel("(p_FEM - p_Hertz) / p0")
    bottom.grid(True, alpha=0.3)
    fig.tight_layout()
    png = "pressure_profile.png"
    fig.savefig(f"{out_dir}/{png}", dpi=120)
    plt.close(fig)
    return [(png, f"{TITLE}: {len(curves)} FEM case(s), scaled by the Hertz contact size and peak pressure.")]


if __name__ == "__main__":
    run_standalone(draw)

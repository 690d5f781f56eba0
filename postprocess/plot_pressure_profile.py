"""Hertz pressure profile: FEM against analytic.

For every successful case of scene kind "hertz" (summary written by
fem::to_json(HertzResult)), draws the FEM contact pressure along the surface
("profile": "r_m", or "x_m" for the plane-strain model, and "p_pa") against
Hertz theory, both scaled by the Hertz values: x / c_H and p / p0_H, with c_H
the contact radius "a_hertz_m" (or half-width "b_hertz_m" for plane strain)
and p0_H "p0_hertz_pa". In these units every Hertz profile is the same
ellipse, p / p0 = sqrt(1 - (x/c)^2). The lower panel shows FEM minus Hertz
("profile"/"p_hertz_pa"), in units of p0_H. A key missing from a hertz
summary is an error naming it and the case.

    /usr/bin/python3 postprocess/plot_pressure_profile.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from rollcheck_store import Figure, Skip, count, label, percent, require, run_standalone

TITLE = "Hertz pressure profile: FEM against analytic"
KIND = "hertz"
INSIDE = 0.9   # the profile's deviation is judged inside this fraction of the contact (the edge is a kink)


def profile(case):
    """The scaled profile of one hertz case and its errors, by name."""
    where = f"case {case.name} ({KIND} summary)"
    s = case.summary
    line = require(s, "model", where) == "plane-strain"
    letter, coordinate = ("b", "x_m") if line else ("a", "r_m")
    curve = require(s, "profile", where)
    inner = f"{where}: profile"
    x = np.asarray(require(curve, coordinate, inner), dtype=float)
    p = np.asarray(require(curve, "p_pa", inner), dtype=float)
    hertz = np.asarray(require(curve, "p_hertz_pa", inner), dtype=float)
    c, p0 = require(s, f"{letter}_hertz_m", where), require(s, "p0_hertz_pa", where)
    order = np.argsort(x)
    return {"x": x[order] / c, "p": p[order] / p0, "hertz": hertz[order] / p0, "letter": letter,
            "p0_error": require(s, "p0_error", where), "size_error": require(s, f"{letter}_error", where)}


def conclusion(case, curve):
    inside = curve["x"] <= INSIDE
    worst = np.abs(curve["p"] - curve["hertz"])[inside].max() if inside.any() else float("nan")
    return (f"{case.name}: FEM peak pressure within {percent(abs(curve['p0_error']))} and contact size "
            f"{curve['letter']} within {percent(abs(curve['size_error']))} of Hertz; the profile departs from "
            f"the Hertz ellipse by at most {percent(worst)} of p0 inside {INSIDE} {curve['letter']} "
            f"({int(inside.sum())} nodes).")


def draw(cases, out_dir):
    curves = [(c, profile(c)) for c in cases if c.ok and c.kind == KIND]
    if not curves:
        raise Skip(f"no successful case of kind '{KIND}' (a [scene] kind = \"{KIND}\" case file, e.g. "
                   f"cases/default/hertz_axisymmetric.toml)")
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 6), sharex=True, gridspec_kw={"height_ratios": [3, 1.3]})
    x_max = max(1.5, min(3.0, max(curve["x"].max() for _, curve in curves)))
    xs = np.linspace(0, x_max, 600)
    top.plot(xs, np.sqrt(np.clip(1 - xs ** 2, 0, None)), "k-", lw=2, label="Hertz: sqrt(1 - (x/c)^2)")
    for case, curve in curves:
        keep = curve["x"] <= x_max
        # A 3D profile holds nodes at every angle about the axis: several pressures at nearly one radius,
        # which a line would join in a zig-zag. Points only there.
        style = "." if require(case.summary, "model", case.name) == "3d" else ".-"
        line, = top.plot(curve["x"][keep], curve["p"][keep], style, ms=3, lw=0.8,
                         label=f"FEM {label(case, ('model', 'degree'))}, c = {curve['letter']}")
        bottom.plot(curve["x"][keep], (curve["p"] - curve["hertz"])[keep], style, ms=3, lw=0.8,
                    color=line.get_color())
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
    shows = (f"The FEM contact pressure along the surface against the Hertz ellipse, scaled by the Hertz contact "
             f"size and peak pressure, for {count(len(curves), KIND + ' case')}; below, FEM minus Hertz in units "
             f"of p0.")
    return [Figure(png, TITLE, shows, " ".join(conclusion(c, curve) for c, curve in curves))]


if __name__ == "__main__":
    run_standalone(draw)

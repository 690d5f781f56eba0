"""Speed against error of the FEM Hertz models (convergence).

For every successful case of scene kind "hertz" (summary written by
fem::to_json(HertzResult)), reads its model, degree, refine, dofs, wall_s,
p0_error and the contact-size error (b_error for the plane-strain model,
a_error otherwise) and draws the absolute relative errors against the wall
time, log-log. The cases of one model and degree form a series ordered by
refine level: with two or more levels it is a convergence curve (joined
points, each labelled with its refine level); a series with a single level is
drawn as a lone marker and the caption says so. When no series has two
levels, nothing is drawn and the note gives the single points' numbers. A key missing from a hertz
summary is an error naming it and the case.

    /usr/bin/python3 postprocess/plot_fem_speed_error.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from rollcheck_store import Figure, Skip, count, percent, require, run_standalone

TITLE = "Speed against error of the FEM Hertz models"
KIND = "hertz"
ERRORS = (("p0_error", "peak pressure p0"), ("size_error", "contact size (a or b)"))


def point(case):
    """The numbers of one hertz case that the plot reads, by name."""
    where = f"case {case.name} ({KIND} summary)"
    get = lambda key: require(case.summary, key, where)
    size_key = "b_error" if get("model") == "plane-strain" else "a_error"
    return {"series": f"{get('model')} P{get('degree')}", "refine": get("refine"), "dofs": get("dofs"),
            "wall_s": get("wall_s"), "p0_error": abs(get("p0_error")), "size_error": abs(get(size_key)),
            "size_name": size_key[0]}


def series_of(cases):
    """{model/degree: [points ordered by refine level]} of the successful hertz cases."""
    series = {}
    for case in cases:
        if case.ok and case.kind == KIND:
            p = point(case)
            series.setdefault(p["series"], []).append(p)
    for points in series.values():
        points.sort(key=lambda p: (p["refine"], p["wall_s"]))
    return dict(sorted(series.items()))


ADVICE = (f"a single point is not a convergence curve: add {KIND} cases of the same model at other refine levels "
          f"to see the error fall with cost")


def conclusion(name, points):
    """What one series says: the error's fall with cost, or the numbers of its single refine level."""
    first, last = points[0], points[-1]
    size = last["size_name"]
    if len({p["refine"] for p in points}) < 2:
        return (f"{name}: a single refine level ({last['refine']}, {last['dofs']} DOFs, {last['wall_s']:.2g} s), "
                f"|p0 error| {percent(last['p0_error'])}, |{size} error| {percent(last['size_error'])}.")
    return (f"{name}: from refine {first['refine']} to {last['refine']} ({first['dofs']} to {last['dofs']} DOFs, "
            f"{first['wall_s']:.2g} to {last['wall_s']:.2g} s), |p0 error| goes from "
            f"{percent(first['p0_error'])} to {percent(last['p0_error'])} and |{size} error| from "
            f"{percent(first['size_error'])} to {percent(last['size_error'])}.")


def draw(cases, out_dir):
    series = series_of(cases)
    if not series:
        raise Skip(f"no successful case of kind '{KIND}' (a [scene] kind = \"{KIND}\" case file, e.g. "
                   f"cases/default/hertz_axisymmetric.toml)")
    if all(len({p["refine"] for p in points}) < 2 for points in series.values()):
        raise Skip(f"{ADVICE}. " + " ".join(conclusion(name, points) for name, points in series.items()))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), sharex=True)
    for ax, (key, name) in zip(axes, ERRORS):
        for k, (label, points) in enumerate(series.items()):
            wall = [p["wall_s"] for p in points]
            error = [max(p[key], 1e-12) for p in points]
            curve = len(points) > 1
            ax.loglog(wall, error, "o-" if curve else "o", color=f"C{k % 10}",
                      label=label + ("" if curve else " (single case)"))
            for p, t, e in zip(points, wall, error):
                ax.annotate(f"r{p['refine']}", (t, e), fontsize=7, xytext=(4, 3), textcoords="offset points")
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel(f"|relative error| of {name}")
        ax.set_title(name, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"{TITLE} (labels: refine level)")
    fig.tight_layout()
    png = "fem_speed_error.png"
    fig.savefig(f"{out_dir}/{png}", dpi=120)
    plt.close(fig)
    n = sum(len(p) for p in series.values())
    shows = (f"The error of the FEM against Hertz theory, peak pressure p0 (left) and contact size (right), "
             f"against the wall time of the solve, log-log: {count(n, KIND + ' case')} in "
             f"{count(len(series), 'model/degree series', 'model/degree series')}, each point labelled with its "
             f"refine level.")
    text = " ".join(conclusion(name, points) for name, points in series.items())
    if any(len({p["refine"] for p in points}) < 2 for points in series.values()):
        text += f" The lone markers: {ADVICE}."
    return [Figure(png, TITLE, shows, text)]


if __name__ == "__main__":
    run_standalone(draw)

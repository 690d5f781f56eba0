"""Per-face contact density on the body's surface.

For every case whose summary holds a per-face contact accumulator, draws the
body from two opposite sides, each face coloured by its contact density
relative to the mean: (c_i / A_i) / (sum c / sum A), so that 1 is uniform
contact and 0 a face never touched. The accumulator is a 1-d array under a
key containing "contact" and one of "count", "density", "time", "hits", with
one entry per face; the face areas come from a key containing "area" (equal
areas assumed without one). The surface is drawn from "vertices" (n x 3) and
"faces" (m x 3) if the summary has them, else as a cloud of the face
centroids (a key containing "centroid", m x 3), each point sized by its area.

    /usr/bin/python3 postprocess/plot_contact_density.py STORE OUT_DIR
"""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from rollcheck_store import Skip, arrays, label, run_standalone

TITLE = "Per-face contact density on the body's surface"
MAX_FIGURES = 6
ACCUMULATOR_WORDS = ("count", "density", "time", "hits")


def face_fields(case):
    """(accumulators {path: array}, areas, centroids, vertices, faces) of a case; empty if it has none."""
    named = dict(arrays(case.summary))
    n_faces = case.summary.get("n_faces")
    one_d = {p: a for p, a in named.items() if a.ndim == 1}
    accumulators = {p: a for p, a in one_d.items()
                    if "contact" in p.split("/")[-1].lower()
                    and any(w in p.split("/")[-1].lower() for w in ACCUMULATOR_WORDS)
                    and (n_faces is None or len(a) == n_faces) and len(a) > 3}
    if not accumulators:
        return {}, None, None, None, None
    m = len(next(iter(accumulators.values())))
    accumulators = {p: a for p, a in accumulators.items() if len(a) == m}
    pick = lambda cond: next((a for p, a in named.items() if cond(p.split("/")[-1].lower(), a)), None)
    areas = pick(lambda k, a: "area" in k and a.ndim == 1 and len(a) == m)
    centroids = pick(lambda k, a: "centroid" in k and a.shape == (m, 3))
    faces = pick(lambda k, a: k == "faces" and a.shape == (m, 3) and a.dtype.kind in "iu")
    vertices = pick(lambda k, a: k == "vertices" and a.ndim == 2 and a.shape[1] == 3)
    return accumulators, areas, centroids, vertices, faces


def relative_density(values, areas, is_density):
    areas = np.ones_like(values, dtype=float) if areas is None else areas
    density = values if is_density else values / areas
    mean = np.sum(density * areas) / np.sum(areas)
    return density / mean if mean > 0 else density


def draw_case(case, path, values, areas, centroids, vertices, faces, out_dir, index):
    density = relative_density(values.astype(float), areas, "density" in path.lower())
    if vertices is None or faces is None:
        if centroids is None:
            return None
        points = centroids
    else:
        points = vertices
    fig = plt.figure(figsize=(11, 5))
    norm = matplotlib.colors.Normalize(vmin=0, vmax=max(np.percentile(density, 99), 1e-12))
    cmap = matplotlib.colormaps["viridis"]
    span = (points.max(axis=0) - points.min(axis=0)).max() / 2
    mid = (points.max(axis=0) + points.min(axis=0)) / 2
    for k, (azim, elev) in enumerate([(35, 25), (215, -25)]):
        ax = fig.add_subplot(1, 2, k + 1, projection="3d")
        if vertices is not None and faces is not None:
            poly = Poly3DCollection(vertices[faces], facecolors=cmap(norm(density)), edgecolors="none")
            ax.add_collection3d(poly)
        else:
            size = 4.0 if areas is None else 4.0 * areas / areas.mean()
            ax.scatter(*centroids.T, c=density, cmap=cmap, norm=norm, s=size, depthshade=False)
        for axis, setter in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
            setter(mid[axis] - span, mid[axis] + span)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=elev, azim=azim)
        ax.set_xlabel("x [m]"); ax.set_ylabel("y [m]"); ax.set_zlabel("z [m]")
        ax.set_title(f"view azimuth {azim} deg, elevation {elev} deg", fontsize=9)
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=fig.axes, shrink=0.7,
                 label="contact density / area-weighted mean (1 = uniform)")
    untouched = np.mean(values == 0)
    fig.suptitle(f"{TITLE}\n{label(case)}: {path}, {len(values)} faces, {100 * untouched:.0f} % never touched")
    png = f"contact_density_{index}.png"
    fig.savefig(f"{out_dir}/{png}", dpi=110)
    plt.close(fig)
    drawn_as = "faces" if vertices is not None and faces is not None else "face centroids"
    return png, (f"{TITLE}, {label(case)} ({path}, drawn as {drawn_as}); colour scale capped at the "
                 f"99th percentile.")


def draw(cases, out_dir):
    figures, candidates = [], 0
    for case in cases:
        if not case.ok:
            continue
        accumulators, areas, centroids, vertices, faces = face_fields(case)
        for path, values in accumulators.items():
            candidates += 1
            if len(figures) < MAX_FIGURES:
                drawn = draw_case(case, path, values, areas, centroids, vertices, faces, out_dir, len(figures))
                if drawn:
                    figures.append(drawn)
    if not figures:
        raise Skip("no case holds per-face contact data with face geometry (a per-face array under a key "
                   "with 'contact' and 'count'/'density'/'time'/'hits', and face centroids or vertices + "
                   "faces; the oracle writes them with --per-face)")
    if candidates > len(figures):
        figures[-1] = (figures[-1][0], figures[-1][1] + f" ({candidates - len(figures)} more not drawn.)")
    return figures


if __name__ == "__main__":
    run_standalone(draw)

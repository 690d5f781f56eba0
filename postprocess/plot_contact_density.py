"""Per-face contact density on the body's surface.

For every case whose summary holds a per-face contact accumulator, draws the
body from two opposite sides, each face coloured by its contact density
relative to the mean, (c_i / A_i) / (sum c / sum A): 1 is uniform contact.
The scale is logarithmic (the densities of a rolling body span orders of
magnitude); faces never touched are grey. The accumulator is a 1-d array
under a key containing "contact" and one of "count", "density", "time",
"hits", one entry per face; face areas come from a key containing "area"
(equal areas assumed without one).

The surface is the summary's "vertices" (n x 3) and "faces" (m x 3) if it
has them. Otherwise it is rebuilt from the case's body parameters by
`rollcheck run` of a "mesh" case (the binary named by $ROLLCHECK_BINARY),
and used only if it has the same number of faces and, where the summary
has face centroids, the same centroids. Failing that, the face centroids
(a key containing "centroid", m x 3) are drawn as points.

    ROLLCHECK_BINARY=build/src/cli/rollcheck /usr/bin/python3 postprocess/plot_contact_density.py STORE OUT_DIR
"""
import json
import os
import subprocess
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from rollcheck_store import Skip, arrays, label, run_standalone

TITLE = "Per-face contact density on the body's surface"
MAX_FIGURES = 6
ACCUMULATOR_WORDS = ("count", "density", "time", "hits")
# The parameters every body scene shares (src/cli/scenes.cpp, body_parameters).
BODY_KEYS = ("body", "family", "theta_deg", "offset", "ratio", "circles", "points", "radius_m", "height_m",
             "sections", "subdivisions", "mesh_file")


def face_fields(case):
    """(accumulators {path: array}, areas, centroids, vertices, faces) of a case; empty if it has none."""
    named = dict(arrays(case.summary))
    n_faces = case.summary.get("n_faces")
    leaf = lambda p: p.split("/")[-1].lower()
    accumulators = {p: a for p, a in named.items()
                    if a.ndim == 1 and "contact" in leaf(p) and any(w in leaf(p) for w in ACCUMULATOR_WORDS)
                    and (n_faces is None or len(a) == n_faces) and len(a) > 3}
    if not accumulators:
        return {}, None, None, None, None
    m = len(next(iter(accumulators.values())))
    accumulators = {p: a for p, a in accumulators.items() if len(a) == m}
    pick = lambda cond: next((a for p, a in named.items() if cond(leaf(p), a)), None)
    areas = pick(lambda k, a: "area" in k and a.ndim == 1 and len(a) == m)
    centroids = pick(lambda k, a: "centroid" in k and a.shape == (m, 3))
    faces = pick(lambda k, a: k == "faces" and a.shape == (m, 3) and a.dtype.kind in "iu")
    vertices = pick(lambda k, a: k == "vertices" and a.ndim == 2 and a.shape[1] == 3)
    return accumulators, areas, centroids, vertices, faces


def toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    return repr(v)


def rebuilt_surface(case, n_faces, centroids):
    """(vertices, faces) of the case's body, rebuilt by rollcheck; None if that fails or does not match."""
    binary = os.environ.get("ROLLCHECK_BINARY")
    if not binary or "body" not in case.parameters:
        return None
    with tempfile.TemporaryDirectory() as tmp:
        obj = os.path.join(tmp, "body.obj")
        with open(os.path.join(tmp, "body.toml"), "w") as f:
            f.write('[scene]\nkind = "mesh"\n')
            for k in BODY_KEYS:
                if k in case.parameters:
                    f.write(f"{k} = {toml_value(case.parameters[k])}\n")
            f.write(f"out = {json.dumps(obj)}\n")
        done = subprocess.run([binary, "-q", "run", os.path.join(tmp, "body.toml")], capture_output=True,
                              timeout=300)
        if done.returncode != 0 or not os.path.exists(obj):
            return None
        vertices, faces = [], []
        with open(obj) as f:
            for line in f:
                if line.startswith("v "):
                    vertices.append([float(x) for x in line.split()[1:4]])
                elif line.startswith("f "):
                    faces.append([int(x.split("/")[0]) - 1 for x in line.split()[1:4]])
    vertices, faces = np.array(vertices), np.array(faces)
    if len(faces) != n_faces:
        return None
    if centroids is not None:
        size = np.ptp(vertices, axis=0).max()
        if np.abs(vertices[faces].mean(axis=1) - centroids).max() > 1e-6 * size:
            return None
    return vertices, faces


def relative_density(values, areas, is_density):
    areas = np.ones_like(values, dtype=float) if areas is None else areas
    density = values if is_density else values / areas
    mean = np.sum(density * areas) / np.sum(areas)
    return density / mean if mean > 0 else density


def draw_case(case, path, values, areas, centroids, surface, out_dir, index):
    density = relative_density(values.astype(float), areas, "density" in path.lower())
    touched = density > 0
    if not touched.any():
        return None
    cmap = matplotlib.colormaps["viridis"]
    norm = matplotlib.colors.LogNorm(vmin=max(density[touched].min(), 1e-3), vmax=density.max())
    colours = np.where(touched[:, None], cmap(norm(np.where(touched, density, 1.0))), [0.8, 0.8, 0.8, 1.0])
    points = surface[0] if surface else centroids
    span = np.ptp(points, axis=0).max() / 2
    mid = (points.max(axis=0) + points.min(axis=0)) / 2
    fig = plt.figure(figsize=(12, 5.5))
    if surface:
        triangles = surface[0][surface[1]]
        centres = triangles.mean(axis=1)
        normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
        # Outward for a convex body, whatever the winding of its faces.
        normals *= np.sign(np.einsum("ij,ij->i", normals, centres - points.mean(axis=0)))[:, None]
    else:
        centres = centroids
        normals = centroids - centroids.mean(axis=0)
    for k, (azim, elev) in enumerate([(35, 25), (215, -25)]):
        ax = fig.add_subplot(1, 2, k + 1, projection="3d")
        a, e = np.radians(azim), np.radians(elev)
        # Only the faces turned towards the viewer: matplotlib sorts polygons
        # by mean depth, which draws hidden slivers on top of visible faces.
        facing = normals @ np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)]) > 0
        if surface:
            ax.add_collection3d(Poly3DCollection(triangles[facing], facecolors=colours[facing], edgecolors="none"))
        else:
            ax.scatter(*centres[facing].T, c=colours[facing], s=6, depthshade=False)
        for axis, setter in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
            setter(mid[axis] - span, mid[axis] + span)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        ax.set_title(f"seen from azimuth {azim} deg, elevation {elev} deg (body frame)", fontsize=9)
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=fig.axes, shrink=0.7,
                 label="contact density / area-weighted mean (1 = uniform)")
    fig.suptitle(f"{TITLE}\n{label(case)}: {path}, {len(values)} faces, "
                 f"{100 * np.mean(~touched):.0f} % never touched (grey)")
    png = f"contact_density_{index}.png"
    fig.savefig(f"{out_dir}/{png}", dpi=110)
    plt.close(fig)
    drawn_as = "its faces" if surface else "face centroids (no surface available)"
    return png, f"{TITLE}: {label(case)}, {path}, drawn as {drawn_as}; logarithmic colour scale."


def draw(cases, out_dir):
    figures, candidates = [], 0
    for case in cases:
        if not case.ok:
            continue
        accumulators, areas, centroids, vertices, faces = face_fields(case)
        if not accumulators:
            continue
        m = len(next(iter(accumulators.values())))
        surface = (vertices, faces) if vertices is not None and faces is not None \
            else rebuilt_surface(case, m, centroids)
        if surface is None and centroids is None:
            continue
        for path, values in accumulators.items():
            candidates += 1
            if len(figures) < MAX_FIGURES:
                drawn = draw_case(case, path, values, areas, centroids, surface, out_dir, len(figures))
                if drawn:
                    figures.append(drawn)
    if not figures:
        raise Skip("no case holds per-face contact data with a surface to draw it on (a per-face array under a "
                   "key with 'contact' and 'count'/'density'/'time'/'hits', and vertices + faces, body "
                   "parameters, or face centroids; the oracle writes them with --per-face)")
    if candidates > len(figures):
        figures[-1] = (figures[-1][0], figures[-1][1] + f" ({candidates - len(figures)} more not drawn.)")
    return figures


if __name__ == "__main__":
    run_standalone(draw)

"""Per-face contact density on the body's surface.

For every successful case of scene kind "oracle" whose summary holds the
per-face arrays ("per_face", written with per_face = true by
study::to_json(BodyScores)), draws the body from two opposite sides, each
face coloured by its contact density relative to the mean,
(c_i / A_i) / (sum c / sum A), from "per_face"/"contact_counts" and
"per_face"/"face_areas_m2": 1 is uniform contact. The scale is logarithmic
(the densities of a rolling body span orders of magnitude); faces never
touched are grey. The surface is rebuilt from the case's body parameters by
`rollcheck run` of a "mesh" case (the binary named by $ROLLCHECK_BINARY) and
used only if it has the summary's "n_faces". An oracle case without per-face
arrays, or whose surface cannot be rebuilt, is named in the caption. A key
missing from a summary is an error naming it and the case.

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

from rollcheck_store import Figure, Skip, label, percent, require, run_standalone

TITLE = "Per-face contact density on the body's surface"
KIND = "oracle"
MAX_FIGURES = 6
# The parameters of a body (cli/scenes.h, body_schema()).
BODY_KEYS = ("body", "family", "theta_deg", "offset", "ratio", "circles", "points", "radius_m", "height_m",
             "sections", "subdivisions", "mesh_file")


def face_fields(case):
    """(contact counts, face areas) per face of an oracle case; None when it was run without per_face."""
    where = f"case {case.name} ({KIND} summary)"
    if require(case.summary, "oracle", where) == "rolling" or "per_face" not in case.summary:
        return None
    per_face = case.summary["per_face"]
    inner = f"{where}: per_face"
    counts = np.asarray(require(per_face, "contact_counts", inner), dtype=float)
    areas = np.asarray(require(per_face, "face_areas_m2", inner), dtype=float)
    n_faces = require(case.summary, "n_faces", where)
    if len(counts) != n_faces or len(areas) != n_faces:
        raise ValueError(f"{where}: per_face arrays of {len(counts)} and {len(areas)} entries for {n_faces} faces")
    return counts, areas


def toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    return repr(v)


def rebuilt_surface(case, n_faces):
    """(vertices, faces) of the case's body rebuilt by rollcheck, or the reason it could not be."""
    binary = os.environ.get("ROLLCHECK_BINARY")
    if not binary:
        return "no rollcheck binary to rebuild its surface (make_report.py --rollcheck)"
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
            return f"rebuilding its surface failed ({done.stderr.decode(errors='replace').strip()[-200:]})"
        vertices, faces = [], []
        with open(obj) as f:
            for line in f:
                if line.startswith("v "):
                    vertices.append([float(x) for x in line.split()[1:4]])
                elif line.startswith("f "):
                    faces.append([int(x.split("/")[0]) - 1 for x in line.split()[1:4]])
    if len(faces) != n_faces:
        return f"its rebuilt surface has {len(faces)} faces, the summary {n_faces}"
    return np.array(vertices), np.array(faces)


def relative_density(counts, areas):
    """Contact density per face over its area-weighted mean (1 = uniform)."""
    density = counts / areas
    mean = np.sum(counts) / np.sum(areas)
    return density / mean if mean > 0 else density


def draw_case(case, density, surface, out_dir, index):
    touched = density > 0
    cmap = matplotlib.colormaps["viridis"]
    norm = matplotlib.colors.LogNorm(vmin=max(density[touched].min(), 1e-3), vmax=density.max())
    colours = np.where(touched[:, None], cmap(norm(np.where(touched, density, 1.0))), [0.8, 0.8, 0.8, 1.0])
    vertices, faces = surface
    span = np.ptp(vertices, axis=0).max() / 2
    mid = (vertices.max(axis=0) + vertices.min(axis=0)) / 2
    fig = plt.figure(figsize=(12, 5.5))
    triangles = vertices[faces]
    centres = triangles.mean(axis=1)
    normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    # Outward for a convex body, whatever the winding of its faces.
    normals *= np.sign(np.einsum("ij,ij->i", normals, centres - vertices.mean(axis=0)))[:, None]
    for k, (azim, elev) in enumerate([(35, 25), (215, -25)]):
        ax = fig.add_subplot(1, 2, k + 1, projection="3d")
        a, e = np.radians(azim), np.radians(elev)
        # Only the faces turned towards the viewer: matplotlib sorts polygons
        # by mean depth, which draws hidden slivers on top of visible faces.
        facing = normals @ np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)]) > 0
        ax.add_collection3d(Poly3DCollection(triangles[facing], facecolors=colours[facing], edgecolors="none"))
        for axis, setter in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
            setter(mid[axis] - span, mid[axis] + span)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        ax.set_title(f"seen from azimuth {azim} deg, elevation {elev} deg (body frame)", fontsize=9)
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=fig.axes, shrink=0.7,
                 label="contact density / area-weighted mean (1 = uniform)")
    fig.suptitle(f"{TITLE}\n{label(case, ('body', 'oracle'))}: {len(density)} faces, "
                 f"{100 * np.mean(~touched):.0f} % never touched (grey)")
    png = f"contact_density_{index}.png"
    fig.savefig(f"{out_dir}/{png}", dpi=110)
    plt.close(fig)
    return png


def draw(cases, out_dir):
    figures, not_drawn = [], []
    for case in cases:
        if not (case.ok and case.kind == KIND):
            continue
        fields = face_fields(case)
        if fields is None:
            not_drawn.append(f"{case.name} (no per-face arrays: run it with per_face = true)")
            continue
        density = relative_density(*fields)
        surface = rebuilt_surface(case, len(density))
        if isinstance(surface, str):
            not_drawn.append(f"{case.name} ({surface})")
        elif not (density > 0).any():
            not_drawn.append(f"{case.name} (no face was touched)")
        elif len(figures) == MAX_FIGURES:
            not_drawn.append(f"{case.name} (more than {MAX_FIGURES} figures)")
        else:
            png = draw_case(case, density, surface, out_dir, len(figures))
            touched = density > 0
            shows = (f"{label(case, ('body', 'oracle'))}: each face coloured by its contact density over the "
                     f"area-weighted mean (1 = uniform contact; logarithmic scale; grey: never touched), seen "
                     f"from two opposite sides.")
            conclusion = (f"{percent(np.mean(~touched))} of the {len(density)} faces are never touched; the "
                          f"touched faces span {density[touched].min():.2g} to {density.max():.3g} times the "
                          f"mean density, where uniform contact would put every face at 1 (the CDS condenses this "
                          f"spread into one number).")
            figures.append(Figure(png, f"{TITLE}: {case.name}", shows, conclusion))
    if not figures:
        raise Skip("no successful oracle case with per-face arrays and a surface to draw them on (an oracle case "
                   "with per_face = true, e.g. cases/default/oracle_rigid_cylinder.toml)"
                   + (f"; left out: {'; '.join(not_drawn)}" if not_drawn else ""))
    if not_drawn:
        figures[-1].conclusion += f" Not drawn: {'; '.join(not_drawn)}."
    return figures


if __name__ == "__main__":
    run_standalone(draw)

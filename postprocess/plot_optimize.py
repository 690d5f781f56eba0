"""Where a roller family's optimum lies: the plot of one optimize run.

Reads OUT/optimize.json (written by `rollcheck optimize --out OUT` or
`rollcheck run cases/optimize_*.toml`) and draws into OUT:
  sweeps.png  the score along each parameter axis through the start (the
              others held there), the start's noise band (+- 2 sigma) and the
              points the search evaluated, projected onto each axis, with the
              optimum marked. Bodies whose score is infinite (FEM-SDS of a
              body that cannot roll a whole loop) are marked as crosses at
              the top of each panel.
  optimum.png a rendered view of the optimum's mesh (OUT/optimum.obj),
              beside the start's (OUT/start.obj) when the folder has it, both
              seen from the same direction at the same scale, each face shaded
              by the cosine between its normal and a light direction.

    /usr/bin/python3 postprocess/plot_optimize.py --out OUT
"""
import os

import matplotlib
from out_folder import read_summary
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

LIGHT = np.array([0.4, -0.5, 0.77]) / np.linalg.norm([0.4, -0.5, 0.77])


def number(value):
    """A JSON number of rollcheck's convention ("inf" for infinity) as a float."""
    return float(value)


def finite_points(xs, ys):
    """The (x, y) pairs with a finite y, and the x of the others."""
    finite = [(x, y) for x, y in zip(xs, map(number, ys)) if y != float("inf")]
    return [p[0] for p in finite], [p[1] for p in finite], [x for x, y in zip(xs, map(number, ys)) if y == float("inf")]


def read_obj(path):
    """The vertices (n x 3) and triangles (m x 3, 0-based) of an OBJ file of triangles."""
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if fields and fields[0] == "v":
                vertices.append([float(v) for v in fields[1:4]])
            elif fields and fields[0] == "f":
                faces.append([int(v.split("/")[0]) - 1 for v in fields[1:4]])
    return np.array(vertices), np.array(faces)


def draw_body(ax, vertices, faces, half_extent, title):
    """The mesh shaded by its faces' outward normals against LIGHT, on a cube of +-half_extent."""
    triangles = vertices[faces]
    normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    # Ambient 0.25 keeps the faces turned away from the light visible.
    brightness = 0.25 + 0.75 * np.clip(normals @ LIGHT, 0, 1)
    colours = plt.cm.Blues(0.15 + 0.85 * brightness)
    ax.add_collection3d(Poly3DCollection(triangles, facecolors=colours, edgecolors="none"))
    centre = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    for set_limits, c in zip([ax.set_xlim, ax.set_ylim, ax.set_zlim], centre):
        set_limits(c - half_extent, c + half_extent)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=22, azim=-58)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title(title, fontsize=8)


def draw_bodies(folder, result):
    """optimum.png: the optimum's mesh, beside the start's when the folder has start.obj."""
    best, mesh = result["optimum"], result["mesh"]
    panels = []
    if os.path.exists(os.path.join(folder, "start.obj")):
        panels.append(("start.obj", "start", result["start"], result["start_value"], mesh["start"]))
    panels.append(("optimum.obj", "optimum", best["x"], best["value"], mesh["optimum"]))
    bodies = [read_obj(os.path.join(folder, name)) for name, *_ in panels]
    half_extent = max(0.5 * (v.max(axis=0) - v.min(axis=0)).max() for v, _ in bodies)
    fig = plt.figure(figsize=(4.6 * len(panels), 4.6))
    for k, ((_, label, x, value, resolution), (vertices, faces)) in enumerate(zip(panels, bodies)):
        ax = fig.add_subplot(1, len(panels), k + 1, projection="3d")
        genome = ", ".join(f"{v:.4g}" for v in x)
        draw_body(ax, vertices, faces, half_extent,
                  f"{label} ({genome})\n{result['score']} {number(value):.4g}, "
                  f"{resolution['faces']} faces ({resolution['points']} points per circle)")
    verdict = "beats the start" if best["beats_start"] else "does not beat the start beyond the noise"
    fig.suptitle(f"{result['family']} family, {result['oracle']} oracle: the optimum {verdict}", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "optimum.png"), dpi=120)
    print("optimum.png: the optimum's mesh" + (" beside the start's" if len(panels) == 2 else ""))


def main():
    out, result = read_summary(__doc__, "optimize.json", "folder holding optimize.json and the meshes; the plots go there")
    names = result["parameters"]
    sweeps = result["sweeps"]
    start, start_value = result["start"], result["start_value"]
    sigma = result["noise"]["sigma"]
    best = result["optimum"]
    history = result["search"]["history"]

    fig, axes = plt.subplots(1, max(len(sweeps), 1), figsize=(4 * max(len(sweeps), 1), 3.6), squeeze=False)
    for ax, sweep in zip(axes[0], sweeps):
        i = sweep["axis"]
        hx, hy, h_inf = finite_points([h["x"][i] for h in history], [h["value"] for h in history])
        ax.plot(hx, hy, ".", color="0.7", ms=4, label="search (all points, projected)")
        sx, sy, s_inf = finite_points(sweep["coordinates"], sweep["values"])
        ax.plot(sx, sy, "o-", color="C0", label="sweep through the start")
        if h_inf or s_inf:
            ax.plot(h_inf + s_inf, [1.0] * len(h_inf + s_inf), "x", color="C3", transform=ax.get_xaxis_transform(),
                    clip_on=False, label="infinite (no whole loop)")
        ax.axhspan(start_value - 2 * sigma, start_value + 2 * sigma, color="C0", alpha=0.12,
                   label="start +- 2 sigma noise")
        ax.plot([start[i]], [start_value], "s", color="C0", mfc="none", ms=9, label="start")
        ax.plot([best["x"][i]], [best["value"]], "*", color="C3", ms=12,
                label="optimum" + (" (beats the start)" if best["beats_start"] else " (within the noise)"))
        ax.set_xlabel(names[i])
        ax.set_ylabel(result["score"])
    axes[0][0].legend(fontsize=7)
    fig.suptitle(f"{result['score']} of the {result['family']} family, {result['oracle']} oracle, "
                 f"{result['mesh']['points_per_circle']} points per circle", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sweeps.png"), dpi=120)
    print("sweeps.png: the score along each axis through the start, and the search's points")
    draw_bodies(out, result)


if __name__ == "__main__":
    main()

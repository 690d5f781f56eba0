#!/usr/bin/python3
"""Where the faces the preprint's oracle never touches lie on its body.

Reads a triangle surface mesh (meshio) and the JSON of `rollcheck oracle --mesh MESH
--paper-compat --per-face --json PATH` on it, and prints the untouched faces'
count and area, the range of each coordinate over their vertices, and the
count and area of the mesh's faces in the plane x = X that holds them all, when
one does (the preprint's body: its flat disc x = 1).

Usage: scripts/studies/untouched_faces.py MESH.obj ORACLE.json
"""
import json
import sys

import meshio
import numpy as np


def main(argv):
    if len(argv) != 3:
        sys.exit(f"usage: {argv[0]} MESH.obj ORACLE.json")
    mesh = meshio.read(argv[1])
    vertices, faces = mesh.points, mesh.get_cells_type("triangle")
    with open(argv[2], encoding="utf-8") as f:
        per_face = json.load(f)["per_face"]
    counts, areas = np.array(per_face["contact_counts"]), np.array(per_face["face_areas_m2"])
    if len(counts) != len(faces):
        sys.exit(f"{argv[2]}: {len(counts)} faces, {argv[1]} has {len(faces)}")
    untouched = counts == 0
    corners = vertices[faces[untouched]]
    print(f"untouched faces: {untouched.sum()} of {len(faces)}, area {areas[untouched].sum():.4f} m^2")
    for axis, name in enumerate("xyz"):
        print(f"  {name} over their vertices: {corners[:, :, axis].min():.6f} ... {corners[:, :, axis].max():.6f}")
    x = corners[:, :, 0]
    if np.ptp(x) < 1e-9:
        in_plane = np.abs(vertices[faces][:, :, 0] - x.flat[0]).max(axis=1) < 1e-9
        print(f"all in the plane x = {x.flat[0]:g}, which holds {in_plane.sum()} faces of area "
              f"{areas[in_plane].sum():.4f} m^2")


if __name__ == "__main__":
    main(sys.argv)

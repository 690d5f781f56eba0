#!/usr/bin/python3
"""A rounded rim end by half-space theory on a graded grid: what sets its peak.

`rollcheck rim`'s rounded end (a straight rim of edge radius r_e at the end of
a line contact of half-width b across a sheet of radius R) costs minutes to
hours in 3D FEM where r_e >> b, because the fillet's boundary layer
s = 2 r_e b / (pi R) is far below b (docs/methods/rims.md, "Where a rounded
loop's time goes"). Where r_e >> b the body is a half-space at the contact's
scale and the end is Hertz's problem with the gap

    h(x, y) = y^2 / (2 R) + max(0, x)^2 / (2 r_e)

(x along the ruling, the fillet starting at x = 0; y across it). In units of
b and line Hertz's p0 the pressure then depends on rho = R / r_e alone, and on
how long the line contact is: the ruling [-L, 0] pressed by a rigid plane,
mirrored at x = -L (as the FEM block's symmetry plane), under the line load
q = pi b p0 / 2. This prototype solves it with constant-pressure cells on a
grid graded in x from s / 8 about the fillet's start (Love's rectangle, K. L.
Johnson, Contact Mechanics, eq. 3.25; mirror images for y = 0 and x = -L) and
a dense active-set solve, and prints the end's peak over the far side's
pressure (the FEM's end / interior) and over p0.

  python3 scripts/studies/rounded_end_half_space.py [--rho 4 --length 400 ...]
  python3 scripts/studies/rounded_end_half_space.py --check   # Hertz's point contact on the same grid

Cost: n cells (4,000-7,000 at the defaults) need an n x n influence matrix
and a few dense solves: 25-120 s a row on one core. The prototype of
`rollcheck rounded-end`, which solves the same grids in C++; kept as its
independent check (tests/cli/rounded_end.sh, scripts/bench/bench_rounded_end.sh).
"""
import argparse
import sys
import time

import numpy as np


def love_term(s, t):
    """The integral of 1 / r over [0, s] x [0, t], odd in s and in t."""
    with np.errstate(divide="ignore", invalid="ignore"):
        a = np.where(s != 0, s * np.arcsinh(t / np.abs(np.where(s != 0, s, 1.0))), 0.0)
        c = np.where(t != 0, t * np.arcsinh(s / np.abs(np.where(t != 0, t, 1.0))), 0.0)
    return a + c


def rectangle_deflection(dx, dy, half_x, half_y):
    """Deflection (E* = 1) at offset (dx, dy) from a cell's centre under unit pressure."""
    return (love_term(dx + half_x, dy + half_y) - love_term(dx + half_x, dy - half_y)
            - love_term(dx - half_x, dy + half_y) + love_term(dx - half_x, dy - half_y)) / np.pi


def graded_edges(start, first, stop, growth, largest):
    """Cell edges from start towards stop, the first cell `first` long, each next growth times longer."""
    edges, size, sign = [start], first, 1.0 if stop > start else -1.0
    while sign * (stop - edges[-1]) > 1e-12:
        edges.append(edges[-1] + sign * min(size, sign * (stop - edges[-1])))
        size = min(size * growth, largest)
    return np.array(edges)


class Grid:
    """Cells of the tensor grid of edges xe, ye (y >= 0, mirrored at y = 0; at x = mirror_x if given)."""

    def __init__(self, xe, ye, mirror_x=None):
        self.xc, self.yc = (xe[1:] + xe[:-1]) / 2, (ye[1:] + ye[:-1]) / 2
        hx, hy = (xe[1:] - xe[:-1]) / 2, (ye[1:] - ye[:-1]) / 2
        x, y = np.meshgrid(self.xc, self.yc, indexing="ij")
        a, c = np.meshgrid(hx, hy, indexing="ij")
        self.x, self.y, a, c = x.ravel(), y.ravel(), a.ravel(), c.ravel()
        self.area = 4 * a * c
        sources_x = [self.x] + ([2 * mirror_x - self.x] if mirror_x is not None else [])
        self.influence = np.zeros((self.x.size, self.x.size))
        for sx in sources_x:
            for sy in (self.y, -self.y):
                self.influence += rectangle_deflection(self.x[:, None] - sx[None, :], self.y[:, None] - sy[None, :],
                                                       a[None, :], c[None, :])

    def field(self, values):
        return values.reshape(self.xc.size, self.yc.size)


def solve_contact(grid, gap, force, loaded):
    """Frictionless contact with a rigid approach: p >= 0, h + u = delta where p > 0, sum p A = force.
    Active set: solve on the loaded cells, drop those pulled, add those penetrated, until neither."""
    for _ in range(100):
        idx = np.flatnonzero(loaded)
        m = idx.size
        system = np.zeros((m + 1, m + 1))
        system[:m, :m] = grid.influence[np.ix_(idx, idx)]
        system[:m, m] = -1.0
        system[m, :m] = grid.area[idx]
        solution = np.linalg.solve(system, np.concatenate([-gap[idx], [force]]))
        p = np.zeros(gap.size)
        p[idx] = solution[:m]
        approach = solution[m]
        clearance = gap + grid.influence @ p - approach
        pulled, penetrated = loaded & (p < 0), ~loaded & (clearance < -1e-12 * abs(approach))
        if not pulled.any() and not penetrated.any():
            return p
        loaded = (loaded & ~pulled) | penetrated
    raise RuntimeError("active set did not settle in 100 passes")


def rounded_end(rho, length, finest, across, core):
    """The rounded end at R / r_e = rho: units b = 1, E* = 1, so p0 = 1 / (2 R)."""
    sheet_radius = 1.0e4
    edge_radius = sheet_radius / rho
    layer = 2 * edge_radius / (np.pi * sheet_radius)  # s / b
    small = finest * layer
    centre = np.arange(-2 * layer, core * layer + small / 2, small)
    xe = np.concatenate([graded_edges(centre[0], small, -length, 1.15, length / 20)[1:][::-1], centre,
                         graded_edges(centre[-1], small, centre[-1] + 2.0, 1.15, 0.125)[1:]])
    ye = np.concatenate([np.arange(0, 1.25 + across / 2, across), graded_edges(1.25, across, 1.75, 1.3, 0.25)[1:]])
    grid = Grid(xe, ye, mirror_x=-length)
    gap = grid.y**2 / (2 * sheet_radius) + np.maximum(0.0, grid.x) ** 2 / (2 * edge_radius)
    p0 = 1 / (2 * sheet_radius)
    force = np.pi / (4 * sheet_radius) * length / 2  # q L over y >= 0
    p = grid.field(solve_contact(grid, gap, force, (grid.x < 0) & (grid.y < 1)))
    if (p[:, -1] > 0).any() or (p[-1, :] > 0).any():
        raise RuntimeError("the contact reaches the grid's border")
    far = p[np.argmin(np.abs(grid.xc + length / 2)), 0]
    peak = p[:, 0].max()
    return dict(cells=grid.x.size, far_over_p0=far / p0, peak_over_far=peak / far, peak_over_p0=peak / p0,
                peak_x_over_s=grid.xc[np.argmax(p[:, 0])] / layer)


def hertz_check():
    """Hertz's sphere (R = 1, E* = 1, F = 1e-3) on a grid graded as the end's: p0 and the contact's radius."""
    radius, force = 1.0, 1e-3
    a = (3 * force * radius / 4) ** (1 / 3)
    p0 = 3 * force / (2 * np.pi * a**2)
    # graded_edges ends on its stop, so the two halves span [-2a, 2a] exactly.
    xe = np.concatenate([graded_edges(-a / 64, a / 64, -2 * a, 1.1, a / 16)[::-1],
                         graded_edges(a / 64, a / 64, 2 * a, 1.1, a / 16)])
    ye = graded_edges(0.0, a / 32, 2 * a, 1.05, a / 16)
    grid = Grid(xe, ye)
    gap = (grid.x**2 + grid.y**2) / (2 * radius)
    p = solve_contact(grid, gap, force / 2, gap < a**2 / (2 * radius))
    loaded = p > 0
    # the contact's radius from its area over y >= 0: pi a^2 / 2
    return dict(p0_error=p.max() / p0 - 1, a_error=np.sqrt(2 * grid.area[loaded].sum() / np.pi) / a - 1, cells=grid.x.size)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rho", type=float, nargs="+", default=[4.0], help="R / r_e")
    parser.add_argument("--length", type=float, nargs="+", default=[400.0], help="L / b, the line contact from its far mirror to the end")
    parser.add_argument("--finest", type=float, default=0.125, help="cells about the fillet's start, in s")
    parser.add_argument("--across", type=float, default=0.0625, help="cells across the contact, in b")
    parser.add_argument("--core", type=float, default=12.0, help="finest cells from -2 s to this many s past the fillet's start")
    parser.add_argument("--check", action="store_true", help="Hertz's point contact on a graded grid instead")
    args = parser.parse_args()
    for name, values, low, high in (("--rho", args.rho, 0, None), ("--length", args.length, 10, None),
                                    ("--finest", [args.finest], 0, 1), ("--across", [args.across], 0, 0.5),
                                    ("--core", [args.core], 2, None)):
        for v in values:
            if not (v > low and (high is None or v <= high)):
                parser.error(f"{name} {v:g}: must be above {low:g}" + (f" and at most {high:g}" if high else ""))
    if args.check:
        r = hertz_check()
        print(f"Hertz sphere, {r['cells']} cells: p0 {100 * r['p0_error']:+.2f} %, a {100 * r['a_error']:+.2f} %")
        return 0 if abs(r["p0_error"]) < 0.005 and abs(r["a_error"]) < 0.01 else 1
    print("| R / r_e | L / b | cells | far side / p0 | peak / far side | peak / p0 | peak at x / s | s |")
    print("|---|---|---|---|---|---|---|---|")
    for rho in args.rho:
        for length in args.length:
            start = time.monotonic()
            r = rounded_end(rho, length, args.finest, args.across, args.core)
            print(f"| {rho:g} | {length:g} | {r['cells']} | {r['far_over_p0']:.4f} | {r['peak_over_far']:.4f} | "
                  f"{r['peak_over_p0']:.4f} | {r['peak_x_over_s']:.2f} | {time.monotonic() - start:.0f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""The oloid's contact at a vertex orientation: where a ruling's sheet has its apex.

The oloid (r1 = radius) is the convex hull of two circles of radius r1 in
perpendicular planes, each through the other's centre: A about the origin in
the xz-plane, B about (r1, 0, 0) in the xy-plane (oracle::line_contact_circles's
frame). Where the body stands so that the centre of mass's foot lies a quarter
of the ruling from one end (c = 1/4), the ruling runs from P, A's point at
-60 deg, to B's far point (2 r1, 0, 0); the ground touches A at P (its normal
is A's radius there) and the ruling is A's tangent at P. The no-tension linear
rule then loads [0, 3/4] of the ruling with its largest line load at P,
q(P) = 2 F / (3 c L) = 8 F / (3 L), while the sheet's radius across the
ruling falls linearly to 0 at P: line Hertz's pressure there has no bound.

This prints the hull's lower surface near P: its height z above the ground
at x' along the ruling from P (negative: beyond P) and y across it, found
exactly as the lowest point over (x', y) on the segments that join A to B
(a hull point of the oloid lies on such a segment), and the sheet's radius
across the ruling y^2 / (2 z) at the smallest y; then line Hertz at P for a
part finished with edge radius r_e (no radius below r_e).

  python3 scripts/studies/oloid_vertex.py [--radius 0.01] [--load 800] [--edge-radius 4e-4]
"""
import argparse
import math


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def scale(a, k):
    return tuple(x * k for x in a)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--radius", type=float, default=0.01, help="r1 of the oloid (m)")
    parser.add_argument("--load", type=float, default=800.0, help="F, the normal load (N)")
    parser.add_argument("--edge-radius", type=float, default=4e-4, help="r_e of the finish (m)")
    parser.add_argument("--youngs-modulus", type=float, default=200e9, help="E of the body (Pa), steel")
    parser.add_argument("--poisson-ratio", type=float, default=0.3, help="nu of the body, steel")
    args = parser.parse_args()
    r = args.radius
    if not (r > 0 and args.load > 0 and args.edge_radius > 0):
        raise SystemExit("oloid_vertex: --radius, --load and --edge-radius must be positive")

    def on_a(t):
        return (r * math.cos(t), 0.0, r * math.sin(t))

    def on_b(t):
        return (r + r * math.cos(t), r * math.sin(t), 0.0)

    P = on_a(-math.pi / 3)
    end = (2 * r, 0.0, 0.0)
    length = math.dist(P, end)
    down = scale(P, 1 / r)                     # into the ground: A's radius at P
    along = scale(sub(end, P), 1 / length)     # the ruling, A's tangent at P
    across = (down[1] * along[2] - down[2] * along[1], down[2] * along[0] - down[0] * along[2],
              down[0] * along[1] - down[1] * along[0])
    ground = dot(P, down)
    centre_of_mass = (r / 2, 0.0, 0.0)         # midway between the centres, by symmetry
    c = dot(sub(centre_of_mass, P), along) / length

    def in_plane(v):
        return dot(v, along), dot(v, across)

    def plane(x):
        return in_plane(sub(x, P))

    def height(x):
        return ground - dot(x, down)

    b_centre, b_x, b_y = plane((r, 0.0, 0.0)), in_plane((1.0, 0.0, 0.0)), in_plane((0.0, 1.0, 0.0))

    def over(t, point):
        """Lowest height over `point` of the segments from A(t) to B."""
        a = on_a(t)
        pa = plane(a)
        dx, dy = point[0] - pa[0], point[1] - pa[1]
        reach = math.hypot(dx, dy)
        if reach < 1e-15:
            return height(a)
        nx, ny = -dy / reach, dx / reach
        # B's projection crosses the line through pa and the point where
        # k0 + kc cos s + ks sin s = 0.
        k0 = nx * (b_centre[0] - pa[0]) + ny * (b_centre[1] - pa[1])
        kc = r * (nx * b_x[0] + ny * b_x[1])
        ks = r * (nx * b_y[0] + ny * b_y[1])
        amplitude = math.hypot(kc, ks)
        if amplitude < abs(k0):
            return math.inf
        phase, spread = math.atan2(ks, kc), math.acos(max(-1.0, min(1.0, -k0 / amplitude)))
        best = math.inf
        for s in (phase + spread, phase - spread):
            b = on_b(s)
            pb = plane(b)
            beyond = ((pb[0] - pa[0]) * dx + (pb[1] - pa[1]) * dy) / reach
            if beyond >= reach:
                best = min(best, height(a) + reach / beyond * (height(b) - height(a)))
        return best

    def lower_surface(point, samples=2000):
        values = [(over(2 * math.pi * i / samples, point), i) for i in range(samples)]
        best, i = min(values)
        lo, hi = 2 * math.pi * (i - 1) / samples, 2 * math.pi * (i + 1) / samples
        for _ in range(80):  # ternary search about the best sample
            m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
            if over(m1, point) < over(m2, point):
                hi = m2
            else:
                lo = m1
        return min(best, over(0.5 * (lo + hi), point))

    e_star = args.youngs_modulus / (1 - args.poisson_ratio ** 2)
    q = 2 * args.load / (3 * c * length)
    print(f"oloid r1 = {r} m: ruling from P = A(-60 deg) to (2 r1, 0, 0), L = {length:.6g} m, c = {c:.6f}; "
          f"loaded [0, {3 * c:.4f}] of it, q(P) = {q:.6g} N/m at F = {args.load} N")
    ys = (2e-5, 5e-5, 1e-4)
    print("\nlower surface height z (m) above the ground; x' from P along the ruling (negative: beyond P), y across it;"
          "\nthe last column the radius across, from the rise between y = 0 and the first y\n")
    print("| x' (m) | z at y = 0 | " + " | ".join(f"y = {y:g} m" for y in ys) + f" | R = y^2 / 2z at y = {ys[0]:g} |")
    print("|---|---|" + "---|" * len(ys) + "---|")
    for x in (1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 0.0, -5e-5, -1e-4, -2e-4, -5e-4, -1e-3):
        z0 = lower_surface((x, 0.0))
        zs = [lower_surface((x, y)) for y in ys]
        radius = ys[0] ** 2 / (2 * (zs[0] - z0))
        print(f"| {x:+.1e} | {z0:.3e} | " + " | ".join(f"{z:.3e}" for z in zs) + f" | {radius:.4g} |")
    half_width = math.sqrt(4 * q * args.edge_radius / (math.pi * e_star))
    peak = math.sqrt(q * e_star / (math.pi * args.edge_radius))
    print(f"\nline Hertz at P on the finished part (R = r_e = {args.edge_radius} m, E* = {e_star:.4g} Pa, rigid plane): "
          f"b = {half_width:.4g} m (b / r_e = {half_width / args.edge_radius:.3f}), p0 = {peak:.4g} Pa")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The rims of a body over its rolling loop (issue 14): every loaded ruling end
of the orientations fem-sds solves directly, modelled in 3D by `rollcheck rim`
at the end's interior angle (90 deg + the rim's lean), line load and radius.

    mpirun is not needed: each rollcheck call runs on RANKS ranks.
    scripts/rim_loop.py BUILD_DIR BODY [--orientations N] [--ranks 2] [--counter-face rigid|steel]
                        [--edge-radius M] [--levels 3] [--out FILE.md]

Prints a Markdown table: per end the lean, the interior angle, the line load,
b, the wedge exponents (rigid plane: Williams; a block of the same steel:
contact/edge_on_elastic_block_exponent.h) and the FEM's verdict (the measured
growth exponent of a sharp edge, or the converged end/interior ratio of a
square, acute or rounded one). The steel counter-face runs on one process.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def run_json(command, env):
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "out.json")
        done = subprocess.run(command + ["--json", path], env=env, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
        if done.returncode != 0:
            sys.exit(f"rim_loop: {' '.join(command)} failed ({done.returncode}):\n{done.stderr[-2000:]}")
        with open(path) as f:
            return json.load(f)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("build", help="build folder holding src/cli/rollcheck")
    parser.add_argument("body", help="oloid, paper-oloid, cylinder, ...")
    parser.add_argument("--orientations", type=int, default=6, help="orientations fem-sds solves directly")
    parser.add_argument("--ranks", type=int, default=2, help="MPI ranks of each rollcheck call")
    parser.add_argument("--counter-face", default="rigid", choices=["rigid", "steel"],
                        help="rigid plane, or a block of the body's steel (one process)")
    parser.add_argument("--edge-radius", type=float, default=0.0, help="r_e of every rim's fillet (m); 0: sharp")
    parser.add_argument("--levels", type=int, default=3, help="edge mesh levels of each end")
    parser.add_argument("--out", help="also write the table to this Markdown file")
    args = parser.parse_args()
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    rollcheck = os.path.join(args.build, "src", "cli", "rollcheck")
    mpi = ["mpirun", "-n", str(args.ranks)] if args.ranks > 1 else []

    loop = run_json(mpi + [rollcheck, "-q", "fem-sds", "--body", args.body, "--orientations",
                           str(args.orientations)], env)
    rows = ["| orientation | end | lean (deg) | interior angle (deg) | q (N/m) | R (mm) | b (um) "
            f"| wedge exponent, {args.counter_face} | exponent, the other counter-face | FEM | s |",
            "|---|---|---|---|---|---|---|---|---|---|---|"]
    for number, orientation in enumerate(loop["per_orientation"]):
        slices = orientation.get("slices") or []
        if not slices:
            continue
        ends = [(0, "start", slices[0]), (1, "end", slices[-1])]
        loaded = [orientation["loaded_from"] == 0, orientation["loaded_to"] == 1]
        for end, name, piece in ends:
            if not loaded[end]:
                continue
            lean = orientation["rim_overhang_deg"][end]
            angle = 90 + lean
            q, radius = piece["load_n_per_m"], piece["radius_m"]
            rim = run_json((mpi if args.counter_face == "rigid" else []) + [
                                  rollcheck, "-q", "rim", "--interior-angle", f"{min(angle, 179.5):.6f}",
                                  "--counter-face", args.counter_face,
                                  "--radius", repr(radius), "--load-per-length", repr(q),
                                  "--edge-radius", repr(args.edge_radius), "--levels", str(args.levels)], env)
            if rim["singular"]:
                verdict = f"singular, measured {rim['measured_exponent']:.3f}"
            elif rim["end_to_interior"] is None:
                verdict = "rounded edge not resolved"
            else:
                verdict = (f"end/interior {rim['end_to_interior']:.3f}"
                           + ("" if rim["converged"] else " (NOT converged)"))
            other = rim["same_material_block_exponent"] if args.counter_face == "rigid" else None
            seconds = sum(level["wall_s"] for level in rim["levels"])
            rows.append(f"| {number} | {name} | {lean:.1f} | {angle:.1f} | {q:.4g} | {radius * 1e3:.3g} "
                        f"| {rim['half_width_m'] * 1e6:.3g} | {rim['wedge_exponent']:.3f} "
                        f"| {'-' if other is None else f'{other:.3f}'} | {verdict} | {seconds:.0f} |")
    table = "\n".join(rows)
    print(f"{args.body}: {len(loop['per_orientation'])} orientations, rims "
          f"{'sharp' if args.edge_radius == 0 else f'rounded r_e = {args.edge_radius:g} m'}, "
          f"counter-face {args.counter_face}\n")
    print(table)
    if args.out:
        with open(args.out + ".tmp", "w") as f:
            f.write(table + "\n")
        os.replace(args.out + ".tmp", args.out)


if __name__ == "__main__":
    main()

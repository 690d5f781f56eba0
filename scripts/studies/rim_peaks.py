#!/usr/bin/python3
"""Peak-stress comparison at the rims (issue 14): `rollcheck rim --body` for
the true oloid, the preprint's body, the cylinder and the family's best
bodies (the FEM-SDS optimum and the real-rolling U optimum of
`rollcheck optimize --family centre-line`, docs/methods/optimize.md), on one
counter-face and edge, and one Markdown table of what each run printed.

    scripts/studies/rim_peaks.py BUILD_DIR [--counter-face rigid|steel] [--ranks 2]
                         [--out FILE.md] [--json-dir DIR] [-- RIM OPTIONS...]

Options after `--` go to every `rollcheck rim` call (e.g. --edge-radius 2e-4
--radius 0.01 --load 5000 --depth 25 --edge-element 0.03125 --levels 4).
A run's JSON and log (with its per-end table) are kept in --json-dir (default:
a temporary folder).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

BODIES = [
    ("oloid", ["--body", "oloid"]),
    ("paper-oloid", ["--body", "paper-oloid"]),
    ("cylinder", ["--body", "cylinder"]),
    ("FEM-SDS template optimum (112.7, 1.000, 0.999)",
     ["--body", "roller", "--family", "centre-line", "--theta", "112.7", "--offset", "1.000", "--ratio", "0.999"]),
    ("U optimum (74.1, 0.757, 1.071)",
     ["--body", "roller", "--family", "centre-line", "--theta", "74.1", "--offset", "0.757", "--ratio", "1.071"]),
]


def score(entry, missing="singular"):
    value = entry["value"]
    if value is None:
        return missing
    if value == "inf" or (isinstance(value, float) and value == float("inf")):
        return "inf"
    return f"{value:.4g}"


def loop_ratio(j):
    """The loop's largest end pressure over its largest interior pressure
    (absent in JSON written before it was added)."""
    if "loop_end_to_interior" not in j:
        return "-"
    value = j["loop_end_to_interior"]
    if value is not None:
        return f"{value:.3f}"
    aware = j["loop_scores"].get("end_aware")
    if aware and aware[0]["singular_ends"] > 0:
        return "singular"
    covered, change = j.get("covered_end_to_interior"), j.get("covered_limit_change")
    if j.get("outside_model_ends", 0) > 0 and covered is not None:
        tolerance = j["loop_scores"]["tolerance"]
        if change is not None and abs(change) >= tolerance:
            return f"undefined; {covered:.3f} over the covered ends, set by the limit on b / R ({100 * change:+.0f} % on halving it)"
        return f"undefined; {covered:.3f} over the covered ends"
    return "singular" if j.get("outside_model_ends", 0) == 0 else "undefined"


def run(command, path, env):
    """One `rollcheck rim` run: its JSON at path, its log (with the per-end
    table) beside it, written as the run goes (a long run can be followed)."""
    log_path = path[:-len(".json")] + ".log"
    with open(log_path, "w") as log:
        log.write(" ".join(command) + "\n")
        log.flush()
        done = subprocess.run(command + ["--json", path], env=env, stdout=subprocess.DEVNULL, stderr=log)
    if done.returncode != 0:
        with open(log_path) as log:
            sys.exit(f"rim_peaks: {' '.join(command)} failed ({done.returncode}):\n{log.read()[-2000:]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("build", help="build folder holding src/cli/rollcheck")
    parser.add_argument("--counter-face", default="rigid", choices=["rigid", "steel"])
    parser.add_argument("--ranks", type=int, default=2, help="MPI ranks of each rollcheck call")
    parser.add_argument("--out", help="also write the table to this Markdown file")
    parser.add_argument("--json-dir", help="keep each body's JSON here")
    parser.add_argument("--only", help="comma-separated body labels to run (default: all)")
    parser.add_argument("--tabulate", action="store_true",
                        help="only tabulate the JSON already in --json-dir (no runs)")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    args = parser.parse_args(argv[:split])
    extra = argv[split + 1:]
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    rollcheck = os.path.join(args.build, "src", "cli", "rollcheck")
    mpi = ["mpirun", "-n", str(args.ranks)] if args.ranks > 1 else []
    folder = args.json_dir or tempfile.mkdtemp(prefix="rim_peaks_")
    os.makedirs(folder, exist_ok=True)
    rows = ["| body | faces | loaded rim ends (samples) | singular ends | ends outside the model (samples) "
            "| worst end / orientation peak (direct ends) "
            "| loop's end peak / interior peak | FEM-SDS | with the ends | FEM-FDS | with the ends "
            "| end table vs direct | flat-rim table (the loop's own flattest ends) | status | run time (s) |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    wanted = set(args.only.split(",")) if args.only else None
    for label, body in BODIES:
        if wanted and label.split(" ")[0] not in wanted and label not in wanted:
            continue
        path = os.path.join(folder, label.split(" ")[0] + f"_{args.counter_face}.json")
        command = mpi + [rollcheck, "rim"] + body + ["--counter-face", args.counter_face] + extra
        # The cylinder keeps the preprint's proportions (height 2 r) when the
        # radius is scaled; its own default height (2 m) would make a rod.
        if body == ["--body", "cylinder"] and "--radius" in extra and "--height" not in extra:
            command += ["--height", str(2 * float(extra[extra.index("--radius") + 1]))]
        if not args.tabulate:
            run(command, path, env)
        with open(path) as f:
            j = json.load(f)
        loop = j["loop_scores"]
        aware = loop.get("end_aware", [{}])[0] if loop.get("end_aware") else None
        singular = aware["singular_ends"] if aware else 0
        outside = f"{aware.get('outside_model_ends', 0)} ({aware.get('outside_model_samples', 0)})" if aware else "-"
        if aware and aware.get("finished_ends", 0) > 0:
            outside += f"; {aware['finished_ends']} taken at R = r_e"
        missing = "singular" if singular > 0 else "undefined"
        worst = j["worst_end_to_interior"]
        table = j["end_table_vs_direct"]
        flat = j.get("flat_rim_table") or []
        flat_text = (f"{len(flat)} nodes from {flat[0]['interior_angle_deg']:.1f} deg, ratios "
                     f"{min(n['ratio'] for n in flat):.3f}-{max(n['ratio'] for n in flat):.3f}"
                     + ("" if all(n["converged"] for n in flat) else " (a node NOT converged)")
                     + (f"; {whole} sides over their whole ruling" if (whole := sum(
                         side.get("whole_ruling", False) for n in flat for side in n["sides"])) else "")
                     + ("; the nodes below refused" if j.get("flat_rim_refused") else "")) if flat else (
            "refused" if j.get("flat_rim_refused") else "-")
        rows.append(
            f"| {label} | {j['interior']['n_faces']} | {loop['loaded_ends']} ({loop['loaded_end_samples']} of {loop['samples']}) "
            f"| {singular} ({100 * singular / max(loop['loaded_ends'], 1):.0f} %) "
            f"| {outside} | {'-' if worst is None else f'{worst:.3f}'} "
            f"| {loop_ratio(j)} "
            f"| {score(loop['fem_sds_rulings'])} | {score(aware['fem_sds'], missing) if aware else '-'} "
            f"| {score(loop['fem_fds_rulings'])} | {score(aware['fem_fds'], missing) if aware else '-'} "
            f"| {'-' if table is None else f'{100 * table:.1f} %'} | {flat_text} | {j['end_aware_status'].split(':')[0]} "
            f"| {j['wall_s']:.0f} |")
        print(rows[-1], flush=True)
    table = "\n".join(rows)
    print(f"\ncounter-face {args.counter_face}, rim options: {' '.join(extra) or '(defaults)'}\n")
    print(table)
    if args.out:
        with open(args.out + ".tmp", "w") as f:
            f.write(table + "\n")
        os.replace(args.out + ".tmp", args.out)


if __name__ == "__main__":
    main()

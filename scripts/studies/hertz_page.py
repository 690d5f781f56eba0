#!/usr/bin/python3
"""Writes docs/results/hertz.md from the JSON of scripts/studies/hertz.sh:
the penalty, convergence and pointwise studies (`rollcheck hertz --study
NAME --json`) and the defaults' runs (`rollcheck hertz --json`, listed with
their commands in OUT/defaults.tsv).

usage: hertz_page.py OUT_DIR "ROLLCHECK --version LINE" > docs/results/hertz.md
"""
import sys

from results_page import load, num, page_main, pct, signed, table

MODEL_LABEL = {"axisymmetric": "axi", "plane-strain": "plane-strain", "3d": "3d"}


def label(r):
    return MODEL_LABEL.get(r["model"], r["model"])


def size_error(r):
    return r["b_error"] if "b_error" in r else r["a_error"]


def ok_runs(study):
    return [r for r in study["runs"] if "failed" not in r]


def failed_rows(study):
    return [f"- {label(r)} P{r['degree']} refine {r['refine']} c {num(r['penalty_c'], 'g')}: failed ({r['failed']})"
            for r in study["runs"] if "failed" in r]


def by(runs, model, c):
    return next(r for r in runs if r["model"] == model and r["penalty_c"] == c)


def penalty_section(study):
    runs = ok_runs(study)
    out = ["## Penalty study (error against c at fixed mesh)\n",
           "`rollcheck hertz --study penalty --out results/hertz` (CSV `hertz_penalty.csv`, plot",
           "`hertz_penalty.png`). Steel, R = 10 mm, 100 N (5 kN/m), P1 at each model's default mesh, one rank.",
           "\"warning\" marks a run flagged `penalty_error_dominates` (the penalty's estimated error above the",
           "mesh's).\n"]
    rows = [[f"{label(r)} P{r['degree']} (refine {r['refine']})", num(r["penalty_c"], "g"), r["newton_its"],
             num(r["wall_s"], ".2f"), signed(size_error(r)), signed(r["p0_error"]),
             num(100 * r["penalty_error_estimate"], ".3f"), num(100 * r["discretisation_error_estimate"], ".3f"),
             "yes" if "penalty_error_dominates" in r["flags"] else ""] for r in runs]
    out += table(["model (mesh)", "c", "Newton its", "wall s", "a or b err %", "p0 err %", "penalty estimate %",
                  "mesh estimate %", "warning"], rows)
    out += failed_rows(study)
    shares = []
    for model in dict.fromkeys(r["model"] for r in runs):
        try:
            c100, c1000 = by(runs, model, 100.0), by(runs, model, 1000.0)
        except StopIteration:
            continue
        shares.append(f"{100 * abs(c100['p0_error'] - c1000['p0_error']):.3f} % ({label(c100)}; its mesh estimate "
                      f"{100 * c100['discretisation_error_estimate']:.3f} %)")
    out += ["The penalty lowers p0 by about p0 R / (kappa a^2) = 0.7 (h_c / a) / c: the \"penalty estimate\"",
            "column follows the measured p0 error where the penalty dominates (small c). Raising c pays until",
            "that falls below the mesh's own error. **Default c = 100**: measured against c = 1000, the",
            "penalty's share of the p0 error is " + ", ".join(shares) + ".\n"]
    return out


def convergence_section(study):
    out = ["## Convergence study (speed against error)\n",
           "`rollcheck hertz --study convergence --out results/hertz` (CSV `hertz_convergence.csv`, plot",
           "`hertz_convergence.png`: |error| of p0 and of a or b against wall time, one curve per model and",
           "degree). Same body and load, c = 100, one rank; depths are the subsurface maxima's.\n"]
    rows = [[label(r), f"P{r['degree']}", r["refine"], num(r["elements_across_contact"], ".1f"), r["dofs"],
             f"{r['newton_its']} / {r['krylov_its']}", num(r["wall_s"], ".2f"), signed(size_error(r)),
             signed(r["p0_error"]), signed(r["p_max_nodal_error"]), signed(r["max_shear_error"]),
             signed(r["max_shear_depth_error"]), signed(r["max_von_mises_error"]), signed(r["max_von_mises_depth_error"])]
            for r in ok_runs(study)]
    out += table(["model", "deg", "refine", "elements across", "DOFs", "Newton / Krylov its", "wall s",
                  "a or b err %", "p0 err %", "nodal p max err %", "tau_max err %", "its depth %", "von Mises err %",
                  "its depth %"], rows)
    out += failed_rows(study)
    out += ["Each model's default (`--refine` unset) is the coarsest level that meets the model's tolerances",
            "(methods: axisymmetric 0.3 %, plane strain 0.5 %, 3D 1 % in a or b and p0) with a margin of at",
            "least 2x; the rows above are the evidence.\n"]
    return out


def pointwise_section(study):
    out = ["## Pointwise study (3D: cost against pointwise error)\n",
           "`rollcheck hertz --study pointwise --out results/hertz` (one rank, one process; CSV",
           "`hertz_pointwise.csv`, plot `hertz_pointwise.png`: |error| of the largest nodal pressure and the",
           "profile's RMS against wall time). Steel, R = 10 mm, 100 N. Pole/edge: the 3D contact's extra refine",
           "levels (`--pole-refine`, `--edge-refine`); recovery: the nodal pressure (`--pressure-recovery`:",
           "lumped F_i / A_i, consistent M p = F, penalty kappa <-g_i>_+, touching: lumped where the node's gap",
           "is closed, 0 where open). The goal is 0.5 % in both pointwise columns.\n"]
    runs = ok_runs(study)
    rows = [[label(r), f"P{r['degree']}", r["refine"], f"{r['pole_refine']}/{r['edge_refine']}",
             r.get("contact_cap", "-"), num(r["penalty_c"], "g"), r["pressure_recovery"], r["dofs"],
             num(r["wall_s"], ".1f"), signed(size_error(r), 3), signed(r["p0_error"], 3), signed(r["p_max_nodal_error"], 3),
             num(100 * r["profile_rms_error"], ".3f"), num(100 * r["profile_rms_error_interior"], ".3f")]
            for r in runs]
    out += table(["model", "deg", "refine", "pole/edge", "cap", "c", "recovery", "DOFs", "wall s", "a err %",
                  "p0 (fit) err %", "nodal p max err %", "profile RMS %", "RMS s < 0.9 a %"], rows)
    out += failed_rows(study)
    within = [r for r in runs if r["model"] == "3d" and abs(r["p_max_nodal_error"]) <= 0.005
              and r["profile_rms_error"] <= 0.005]
    out += [f"3D setups within 0.5 % in both pointwise columns: {len(within)} of "
            f"{sum(r['model'] == '3d' for r in runs)} (P2 on the cap's rings with the touching recovery is the 3D "
            "default). Why the others miss it:",
            "[methods](../methods/hertz-fem.md#pointwise-accuracy-in-3d).\n"]
    return out


def defaults_section(out_dir):
    out = ["## The defaults, measured\n",
           "Each model's default run, and the 3D one with other radii, materials and loads (steel, R = 10 mm,",
           "100 N unless given); the 3D default is P2 on the cap's rings, read by the touching recovery:\n"]
    rows = []
    for line in (out_dir / "defaults.tsv").read_text().splitlines():
        name, command = line.split("\t")
        r = load(out_dir / f"default_{name}.json")
        c = "b" if "b_error" in r else "a"
        result = (f"{c} {pct(size_error(r), 3)}, p0 {pct(r['p0_error'], 3)}, largest nodal p "
                  f"{pct(r['p_max_nodal_error'], 3)}, profile RMS {100 * r['profile_rms_error']:.3f} %, "
                  f"force {r['force_error']:+.1e}, "
                  f"tau_max {pct(r['max_shear_error'])} at depth {pct(r['max_shear_depth_error'])}")
        cost = (f"{r['dofs']} DOFs, {r['newton_its']} Newton / {r['krylov_its']} Krylov its, {r['load_steps']} load "
                f"steps, {r['peak_memory_mb']:.0f} MB on rank 0")
        rows.append([f"`{command}`", result, cost])
    out += table(["run", "result", "cost"], rows)
    return out


def body(out_dir):
    return (["Wall times are one run's on one machine: compare them with each other, not across machines.\n"]
            + penalty_section(load(out_dir / "hertz_penalty.json"))
            + convergence_section(load(out_dir / "hertz_convergence.json"))
            + pointwise_section(load(out_dir / "hertz_pointwise.json")) + defaults_section(out_dir))


def main(argv):
    page_main(argv, __doc__, "Hertz FEM: studies and measured defaults", "hertz.sh [ROLLCHECK] [OUT_DIR]",
              "`rollcheck hertz --study penalty|convergence|pointwise` and the defaults' runs",
              "[Hertz FEM](../methods/hertz-fem.md)", body)

if __name__ == "__main__":
    main(sys.argv)

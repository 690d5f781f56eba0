"""The report of a rollcheck results store: report.md (the PNGs beside it)
and report.html (the same, PNGs embedded: one self-contained file), rendered
from templates/report.md.j2 and templates/report.html.j2 (Jinja2).

In order (docs/guide/report.md): 1. findings: what rollcheck found about the
preprint, the headline figure (findings.py, from --audit and --robustness, the
JSON of `rollcheck robustness --json`) and each finding with its evidence plot;
2. verdicts: the validation checks (--validation, the JSON `rollcheck validate`
writes) and the status of every case; 3. the audit of the preprint's claims
(--audit, the JSON of `rollcheck audit --json`); 4. the plots, each with what it
shows and what to conclude; 5. FEM against analytic SDS; 6. rolling-contact
fatigue life (--life, the JSON of `rollcheck life --json`: the life ratios as a
figure and a table, the rounded rim ends); appendix: the raw scalar results and parameters per
scene kind, the files the cases wrote. An optional input not given is a
section saying how to get it; a key missing from an input is an error naming
it (exit 1). `rollcheck report --from STORE` runs this in a temporary folder
that replaces the report folder when it succeeds.

    /usr/bin/python3 postprocess/make_report.py --store STORE --out DIR [--rollcheck BINARY]
        [--validation VALIDATION.json] [--audit AUDIT.json] [--robustness ROBUSTNESS.json]
        [--life LIFE.json]
"""
import argparse
import base64
import json
import os
import re
import sys
from dataclasses import dataclass, field

import jinja2
import markupsafe
import numpy as np

import findings
import plot_cds_convergence
import plot_contact_density
import plot_fem_sds
import plot_fem_speed_error
import plot_headline
import plot_life
import plot_pressure_profile
import plot_robustness
from rollcheck_store import Figure, MissingKey, Skip, count, is_number, load_cases, require

PLOTS = (plot_pressure_profile, plot_fem_speed_error, plot_cds_convergence, plot_contact_density)
TEMPLATES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "templates")
WIDE = 8          # more cases of one scene kind than this: the raw table is split
NOTE = 60         # a longer text result goes below its table, as a note
NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$|^-?inf$")
# The claim's `true` verdict (audit/table.h): "depends on CHOICES" is partial.
TRUE_CLASS = {"holds": "pass", "does not hold": "fail", "cannot be tested": "none"}


def true_class(verdict):
    if verdict.startswith("depends on"):
        return "partial"
    if verdict not in TRUE_CLASS:
        raise BadInput(f"unknown `true` verdict '{verdict}' (known: {', '.join(TRUE_CLASS)}, depends on ...)")
    return TRUE_CLASS[verdict]


def two_verdicts(claim, at):
    """The claim's `reproduced` and `true` verdicts, each with its reason."""
    texts = []
    for key in ("reproduced", "true"):
        v = require(claim, key, at)
        texts.append(f"{require(v, 'verdict', f'{at}/{key}')}: {require(v, 'reason', f'{at}/{key}')}")
    return texts


def cell(v):
    """A value as table text."""
    if v is None:
        return "-"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return f"{v:.6g}"
    if isinstance(v, np.ndarray):
        return "x".join(map(str, v.shape)) + " array"
    return str(v).replace("\n", " ")


@dataclass
class Table:
    """A table for the templates: text cells, and a CSS class per row ("pass", "fail", ...)."""
    header: list
    rows: list
    row_class: list = field(default_factory=list)

    def __post_init__(self):
        self.rows = [[cell(v) for v in r] for r in self.rows]
        self.row_class = self.row_class or [""] * len(self.rows)


class BadInput(Exception):
    """An optional input that cannot be read or contradicts itself."""


def read_json(path, option):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, json.JSONDecodeError) as error:
        raise BadInput(f"{option} '{path}': {error}") from None


def validation(path):
    """The verdicts of `rollcheck validate`: counts and a table, failed checks first."""
    where = f"--validation {path}"
    data = read_json(path, "--validation")
    checks = require(data, "checks", where)
    keys = ("case", "kind", "pointer", "criterion", "measured", "reference")
    rows = []
    for k, check in enumerate(checks):
        at = f"{where}: checks/{k}"
        rows.append((bool(require(check, "passed", at)), [require(check, key, at) for key in keys]))
    passed = sum(ok for ok, _ in rows)
    stated = (require(data, "passed", where), require(data, "failed", where))
    if stated != (passed, len(rows) - passed):
        raise BadInput(f"{where}: says {stated[0]} passed and {stated[1]} failed, but its checks hold "
                         f"{passed} passed and {len(rows) - passed} failed")
    rows.sort(key=lambda r: r[0])
    return {"passed": passed, "failed": len(rows) - passed,
            "table": Table(["result", "case", "scene", "value (JSON pointer)", "criterion", "measured", "reference"],
                           [["PASS" if ok else "FAIL"] + r for ok, r in rows],
                           ["pass" if ok else "fail" for ok, _ in rows])}


def audit_cell(cell_json, at):
    """One recomputation as `rollcheck audit` prints it (audit/table.cpp, cell_text)."""
    if not require(cell_json, "applicable", at):
        return "n/a"
    if not require(cell_json, "built", at):
        return "not built yet"
    undecided = cell_json.get("undecided", "")
    mark = f" ({undecided})" if undecided else "" if require(cell_json, "holds", at) else " (✗)"
    return f"{require(cell_json, 'value', at)}{mark} [{', '.join(require(cell_json, 'commands', at))}]"


def audit(path):
    """The claim table of `rollcheck audit --json` (keys of study::to_json(AuditTable))."""
    where = f"--audit {path}"
    data = read_json(path, "--audit")
    modes = [(require(m, "mode", f"{where}: modes/{k}"), require(m, "meaning", f"{where}: modes/{k}"))
             for k, m in enumerate(require(data, "modes", where))]
    rows, classes, rules = [], [], []
    for k, claim in enumerate(require(data, "claims", where)):
        at = f"{where}: claims/{k}"
        cells = require(claim, "recomputations", at)
        reproduced, true = two_verdicts(claim, at)
        rows.append([require(claim, "claim", at), reproduced, true, require(claim, "paper_value", at)]
                    + [audit_cell(cells[m], f"{at}/recomputations/{m}") if m in cells else "n/a" for m, _ in modes])
        classes.append(true_class(claim["true"]["verdict"]))
        note = require(claim, "note", at)
        rules.append(f"{rows[-1][0]}: {require(claim, 'rule', at)}" + (f" {note}" if note else ""))
    commands = []
    for k, command in enumerate(require(data, "commands", where)):
        at = f"{where}: commands/{k}"
        reads = ", ".join(f"{p} = {cell(v)}" for p, v in require(command, "reads", at).items())
        commands.append([require(command, "id", at), require(command, "command", at), reads])
    verdicts = [c["true"]["verdict"] for c in require(data, "claims", where)]
    kinds = sorted(set(verdicts), key=verdicts.index)
    tally = ", ".join(f"{v}: {verdicts.count(v)}" for v in kinds)
    return {"summary": f"{count(len(rows), 'claim')}: {tally}.", "modes": modes, "rules": rules,
            "verdict_rules": require(data, "verdict_rules", where),
            "quick": require(data, "quick", where), "wall_s": require(data, "wall_s", where),
            "table": Table(["claim", "reproduced", "true", "paper"] + [m for m, _ in modes], rows, classes),
            "commands": Table(["id", "command", "values read"], commands)}


def cases_table(cases):
    return Table(["case", "scene", "status", "wall s", "message"],
                 [[c.name, c.kind or "-", c.attrs.get("status", "?"),
                   f"{c.attrs['wall_s']:.2f}" if is_number(c.attrs.get("wall_s")) else "-",
                   c.attrs.get("message", "")] for c in cases],
                 ["" if c.ok else "fail" for c in cases])


def figures(module, cases, out_dir):
    """A plot module's figures, or the stated reason it drew none."""
    try:
        return {"title": module.TITLE, "module": module, "figures": module.draw(cases, out_dir), "skip": None,
                "in_findings": False}
    except Skip as note:
        return {"title": module.TITLE, "module": module, "figures": [], "skip": str(note).rstrip(".") + ".",
                "in_findings": False}


def raw_results(cases):
    """Per scene kind: a table of every case's top-level results, and its parameters (common, varying)."""
    kinds = []
    for c in cases:
        if c.ok and c.kind not in kinds:
            kinds.append(c.kind)
    out = []
    for kind in kinds:
        group = [c for c in cases if c.ok and c.kind == kind]
        values = [{k: v for k, v in c.summary.items() if not isinstance(v, (dict, list, np.ndarray))}
                  for c in group]
        notes = dict.fromkeys((k, v) for r in values for k, v in r.items() if isinstance(v, str) and len(v) > NOTE)
        keys = list(dict.fromkeys(k for v in values for k, x in v.items() if (k, x) not in notes))
        tables = [Table(["quantity"] + [c.name for c in group[i:i + WIDE]],
                        [[k] + [v.get(k) for v in values[i:i + WIDE]] for k in keys])
                  for i in range(0, len(group), WIDE)]
        nested = sorted({k for c in group for k, v in c.summary.items() if isinstance(v, (dict, list, np.ndarray))})
        names = [k for k in group[0].parameters if k != "kind"]
        varying = [k for k in names if len({cell(c.parameters.get(k)) for c in group}) > 1]
        out.append({"kind": kind, "title": f"Scene '{kind}': {count(len(group), 'case')}", "tables": tables,
                    "notes": [f"{k}: {v}" for k, v in notes], "nested": nested,
                    "common": ", ".join(f"{k} = {cell(group[0].parameters[k])}" for k in names if k not in varying),
                    "varying": Table(["case"] + varying, [[c.name] + [c.parameters.get(k) for k in varying]
                                                          for c in group]) if varying else None})
    return out


def ratio_text(x):
    return "-" if x is None else f"{x:.3g}"


def life(path, out):
    """The life study of `rollcheck life --json` (study/life/life_json.cpp): its figure, the comparisons under the
    orthogonal shear (Lundberg-Palmgren's ratio is the same for both criteria) and the rim ends' table."""
    where = f"--life {path}"
    data = read_json(path, "--life")
    rows, classes = [], []
    for k, c in enumerate(require(data, "comparisons", where)):
        at = f"{where}: comparisons/{k}"
        if require(c, "criterion", at) != "orthogonal_shear":
            continue
        verdict, hi = require(c, "verdict", at), require(c, "life_ratio_max", at)
        rows.append([require(c, "name", at), f"{require(c, 'load_n', at):.4g}", require(c, "model", at), verdict,
                     ratio_text(require(c, "life_ratio_min", at)), ratio_text(hi),
                     require(c, "untested_because", at) or ""])
        classes.append("none" if verdict == "cannot be tested" else "partial" if verdict != "robust"
                       else "fail" if hi is not None and hi < 1 else "pass")
    rims = require(data, "rims", where)
    at_re = require(rims, "rim_study_edge_radius_over_radius", f"{where}: rims")
    rim_rows = []
    for k, x in enumerate(require(rims, "lives", f"{where}: rims")):
        at = f"{where}: rims/lives/{k}"
        row = next((r for r in require(x, "rows", at) if r["edge_radius_over_radius"] == at_re), None)
        if row is None:
            continue
        rim_rows.append([x["body"], f"{x['load_n']:.4g}", ratio_text(row["life_with_over_without_ends"]),
                         ratio_text(x["interior_life_ratio_to_cylinder"]),
                         ratio_text(row["life_ratio_to_cylinder_with_ends"]), require(x, "interior_governs", at),
                         ratio_text(x["interior_governs_from_edge_radius_over_radius"])])
    plot_life.draw(data, os.path.join(out, "life.png"))
    figure = Figure("life.png", "Rolling-contact fatigue life against the cylinder's, and the rim ends",
                    "Top: each body's L10 life over the cylinder's at the same load and steel (Lundberg-Palmgren, "
                    "orthogonal shear) over the rolling energy; the band spans the load rules and end margins, the "
                    "line is the dynamic load at a 5 % margin. Bottom: each body's L10 life with its rounded rim "
                    "ends over without them against the edge radius, at each load (the grid's default cell).",
                    "Below 1 on top the cylinder lives longer; on the bottom, below the dashed line the rim ends "
                    "govern the life.")
    return {"figure": figure,
            "comparisons": Table(["comparison", "load N", "model", "verdict", "life ratio min", "life ratio max",
                                  "cannot be tested because"], rows, classes),
            "rims": Table(["body", "load N", f"L10 with ends / without (r_e = {at_re:g} r1)",
                           "L10 / cylinder's, without ends", "with ends", "which governs", "interior from r_e / r1"],
                          rim_rows),
            "wall_s": require(data, "wall_s", where)}


def findings_section(args, plots, fem_sds):
    """The findings: the opening paragraph, the headline figure and each finding with its evidence plot."""
    audit_data = read_json(args.audit, "--audit") if args.audit else None
    robustness = read_json(args.robustness, "--robustness") if args.robustness else None
    rows, paragraph = findings.headline(audit_data, robustness)
    drawn = {"fem_sds": fem_sds["figures"] or fem_sds["skip"]}
    fem_sds["in_findings"] = bool(fem_sds["figures"])
    for plot in plots:
        if plot["module"] is plot_pressure_profile:
            drawn["pressure_profile"] = plot["figures"] or plot["skip"]
            plot["in_findings"] = bool(plot["figures"])
    try:
        drawn["headline"] = [plot_headline.draw(rows, args.out)]
    except Skip as note:
        drawn["headline"] = str(note)
    if robustness:
        plot_robustness.draw(robustness, os.path.join(args.out, "robustness.png"), ["oloid vs cylinder"])
        drawn["robustness"] = [Figure("robustness.png", "The oloid against the cylinder over the modelling choices",
                                      "Each score's oloid / cylinder ratio over the rolling energy: the band spans "
                                      "every other choice, the line is the default choices.", "")]
    return {"paragraph": paragraph, "headline": drawn["headline"],
            "each": findings.items(audit_data, robustness, drawn)}


def context(args, root, cases):
    """Everything the templates show, computed from the inputs."""
    ok = sum(c.ok for c in cases)
    plots = [figures(m, cases, args.out) for m in PLOTS]
    fem_sds = figures(plot_fem_sds, cases, args.out)
    return {
        "store": args.store, "layout": root.get("layout", "?"), "version": root.get("rollcheck_version", "?"),
        "created": root.get("created_utc", "?"),
        "case_summary": f"{count(len(cases), 'case')}: {ok} ok, {len(cases) - ok} not ok",
        "cases_ok": ok == len(cases), "cases": cases_table(cases),
        "validation": validation(args.validation) if args.validation else None,
        "audit": audit(args.audit) if args.audit else None,
        "findings": findings_section(args, plots, fem_sds),
        "plots": plots,
        "fem_sds": fem_sds,
        "fem_sds_table": Table(*plot_fem_sds.table(cases)),
        "life": life(args.life, args.out) if args.life else None,
        "raw": raw_results(cases),
        "files": Table(["case", "file"], [[c.name, f] for c in cases for f in c.files]),
    }


def render(values, out_dir):
    """report.md and report.html from the templates."""
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(TEMPLATES), undefined=jinja2.StrictUndefined,
                             trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True)

    def data_uri(png):
        with open(os.path.join(out_dir, png), "rb") as f:
            return "data:image/png;base64," + base64.b64encode(f.read()).decode("ascii")
    env.filters["data_uri"] = data_uri
    env.filters["md_cell"] = lambda s: str(s).replace("|", "\\|")
    env.filters["numeric"] = lambda s: bool(NUMBER.match(s))
    # Markdown `code` in texts written for Markdown (the audit's), as HTML.
    env.filters["ticks"] = lambda s: markupsafe.Markup(re.sub(r"`([^`]+)`", r"<code>\1</code>",
                                                               str(markupsafe.escape(s))))
    for name, autoescape in (("report.md", False), ("report.html", True)):
        env.autoescape = autoescape
        text = env.get_template(name + ".j2").render(**values)
        with open(os.path.join(out_dir, name), "w") as f:
            f.write(re.sub(r"\n{3,}", "\n\n", text))  # the blank lines around the templates' blocks


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--store", required=True, help="results store (results.h5)")
    parser.add_argument("--out", required=True, help="folder for report.md, report.html and the PNGs")
    parser.add_argument("--rollcheck", help="the rollcheck binary, for plots that rebuild a body's surface")
    parser.add_argument("--validation", help="the checks JSON written by `rollcheck validate` (default: none)")
    parser.add_argument("--audit", help="the JSON of `rollcheck audit --json PATH` (default: none)")
    parser.add_argument("--robustness", help="the JSON of `rollcheck robustness --json PATH` (default: none)")
    parser.add_argument("--life", help="the JSON of `rollcheck life --json PATH` (default: none)")
    args = parser.parse_args()
    if args.rollcheck:
        os.environ["ROLLCHECK_BINARY"] = args.rollcheck
    root, cases = load_cases(args.store)
    os.makedirs(args.out, exist_ok=True)
    try:
        values = context(args, root, cases)
    except (MissingKey, BadInput) as error:
        sys.exit(f"make_report.py: {error}")
    render(values, args.out)
    # Names inside the report folder: --out is a temporary folder renamed into place afterwards.
    print("report: report.html, report.md")


if __name__ == "__main__":
    sys.exit(main())

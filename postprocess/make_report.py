"""The report of a rollcheck results store: report.md (the PNGs beside it)
and report.html (the same, PNGs embedded, one self-contained file).

Sections: the cases and their status; every plot of the plot_*.py modules
that the store has data for (each says what it needs when it has none); per
scene kind, the scalar results and the parameters that vary; the files the
cases wrote (FEM fields as XDMF). `rollcheck report --from STORE` runs it in
a temporary folder that replaces the report folder when it succeeds.

    /usr/bin/python3 postprocess/make_report.py --store STORE --out DIR [--rollcheck BINARY]
"""
import argparse
import base64
import html
import os
import sys
import traceback

import numpy as np

import plot_cds_convergence
import plot_contact_density
import plot_fem_sds
import plot_fem_speed_error
import plot_pressure_profile
from rollcheck_store import Skip, is_number, load_cases, scalars, walk

PLOTS = (plot_cds_convergence, plot_contact_density, plot_pressure_profile, plot_fem_speed_error, plot_fem_sds)
WIDE = 8          # more result columns than this: one row per quantity instead
TABLE_TEXT = 40   # longer strings go below a table as notes


def cell(v):
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


class Report:
    """Blocks (heading, text, table, image) rendered to Markdown and to HTML."""

    def __init__(self, out_dir):
        self.out_dir, self.blocks = out_dir, []

    def heading(self, level, text):
        self.blocks.append(("heading", level, text))

    def text(self, text):
        self.blocks.append(("text", text))

    def table(self, header, rows):
        self.blocks.append(("table", header, [[cell(v) for v in r] for r in rows]))

    def image(self, png, caption):
        self.blocks.append(("image", png, caption))

    def markdown(self):
        out = []
        for b in self.blocks:
            if b[0] == "heading":
                out.append("#" * b[1] + " " + b[2])
            elif b[0] == "text":
                out.append(b[1])
            elif b[0] == "table":
                esc = lambda s: s.replace("|", "\\|")
                out.append("| " + " | ".join(map(esc, b[1])) + " |")
                out.append("|" + "|".join("---" for _ in b[1]) + "|")
                out.extend("| " + " | ".join(map(esc, r)) + " |" for r in b[2])
            elif b[0] == "image":
                out.append(f"![{b[2]}]({b[1]})\n\n*{b[2]}*")
            out.append("")
        return "\n".join(out)

    def html(self, title):
        out = [f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{html.escape(title)}</title><style>"
               "body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}"
               "table{border-collapse:collapse;margin:0.5em 0 1.5em;font-size:0.85em}"
               "th,td{border:1px solid #ccc;padding:3px 7px;text-align:left}th{background:#eee}"
               "td.n{text-align:right;font-family:monospace}img{max-width:100%;border:1px solid #ddd}"
               "figcaption{font-style:italic;font-size:0.9em;margin-bottom:2em}</style></head><body>"]
        numeric = lambda s: s.replace(".", "", 1).replace("e", "", 1).replace("-", "").replace("+", "").isdigit()
        for b in self.blocks:
            if b[0] == "heading":
                out.append(f"<h{b[1]}>{html.escape(b[2])}</h{b[1]}>")
            elif b[0] == "text":
                out.append(f"<p>{html.escape(b[1]).replace('`', '')}</p>")
            elif b[0] == "table":
                out.append("<table><tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in b[1]) + "</tr>")
                for r in b[2]:
                    out.append("<tr>" + "".join(
                        f"<td class='n'>{html.escape(v)}</td>" if numeric(v) else f"<td>{html.escape(v)}</td>"
                        for v in r) + "</tr>")
                out.append("</table>")
            elif b[0] == "image":
                with open(os.path.join(self.out_dir, b[1]), "rb") as f:
                    data = base64.b64encode(f.read()).decode("ascii")
                out.append(f"<figure><img src='data:image/png;base64,{data}' alt='{html.escape(b[2])}'>"
                           f"<figcaption>{html.escape(b[2])}</figcaption></figure>")
        out.append("</body></html>")
        return "\n".join(out)


def overview(report, store, root, cases):
    report.heading(1, "rollcheck report")
    report.text(f"Store `{store}` (layout {root.get('layout', '?')}), rollcheck {root.get('rollcheck_version', '?')}, "
                f"written {root.get('created_utc', '?')}: {root.get('n_cases', len(cases))} case(s), "
                f"{root.get('n_ok', '?')} ok, {root.get('n_failed', '?')} failed, "
                f"{root.get('n_not_run', 0)} not run.")
    report.heading(2, "Cases")
    report.table(["case", "scene", "status", "wall s", "message"],
                 [[c.name, c.kind or "-", c.attrs.get("status", "?"),
                   f"{c.attrs['wall_s']:.2f}" if is_number(c.attrs.get("wall_s")) else "-",
                   c.attrs.get("message", "")] for c in cases])


def plots(report, cases, out_dir):
    report.heading(2, "Plots")
    for module in PLOTS:
        try:
            for png, caption in module.draw(cases, out_dir):
                report.image(png, caption)
        except Skip as note:
            report.text(f"**{module.TITLE}**: not drawn, {note}.")
        except Exception:
            traceback.print_exc()
            report.text(f"**{module.TITLE}**: FAILED to draw: {traceback.format_exc().splitlines()[-1]}")


def table_values(summary):
    """The summary's top-level scalars, and its lists of strings (flags, notes) joined."""
    values = scalars(summary)
    for k, v in summary.items():
        if isinstance(v, list) and all(isinstance(x, str) for x in v):
            values[k] = ", ".join(v) if v else "-"
    return values


def results_by_kind(report, cases):
    kinds = []
    for c in cases:
        if c.ok and c.kind not in kinds:
            kinds.append(c.kind)
    for kind in kinds:
        group = [c for c in cases if c.ok and c.kind == kind]
        report.heading(2, f"Scene '{kind}': {len(group)} case(s)")
        values = [table_values(c.summary) for c in group]
        keys, notes = [], {}
        for v in values:
            for k, x in v.items():
                if isinstance(x, str) and len(x) > TABLE_TEXT:
                    notes.setdefault((k, x), None)
                elif k not in keys:
                    keys.append(k)
        if len(keys) > WIDE:
            for start in range(0, len(group), WIDE - 1):
                part = slice(start, start + WIDE - 1)
                report.table(["quantity"] + [c.name for c in group[part]],
                             [[k] + [v.get(k) for v in values[part]] for k in keys])
        elif keys:
            report.table(["case"] + keys, [[c.name] + [v.get(k) for k in keys] for c, v in zip(group, values)])
        for k, x in notes:
            report.text(f"{k}: {x}")
        shapes = {p: v.shape for p, v in walk(group[0].summary) if isinstance(v, np.ndarray) and v.ndim > 0}
        if shapes:
            report.text("Arrays in each case's summary (in the store): " + ", ".join(
                f"{p} ({'x'.join(map(str, s))})" for p, s in shapes.items()) + ".")
        params = [c.parameters for c in group]
        names = [k for k in params[0] if k != "kind"]
        varying = [k for k in names if len({cell(p.get(k)) for p in params}) > 1]
        constant = [k for k in names if k not in varying]
        report.text("Parameters common to these cases: "
                    + ", ".join(f"{k} = {cell(params[0][k]) or chr(34) * 2}" for k in constant) + ".")
        if varying:
            report.table(["case"] + varying, [[c.name] + [c.parameters.get(k) for k in varying] for c in group])


def files(report, cases):
    rows = [[c.name, f] for c in cases for f in c.files]
    if rows:
        report.heading(2, "Files written by the cases")
        report.text("Paths relative to the store's folder; XDMF files open in ParaView.")
        report.table(["case", "file"], rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--store", required=True, help="results store (results.h5)")
    parser.add_argument("--out", required=True, help="folder for report.md, report.html and the PNGs")
    parser.add_argument("--rollcheck", help="the rollcheck binary, for plots that rebuild a body's surface")
    args = parser.parse_args()
    if args.rollcheck:
        os.environ["ROLLCHECK_BINARY"] = args.rollcheck
    root, cases = load_cases(args.store)
    os.makedirs(args.out, exist_ok=True)
    report = Report(args.out)
    overview(report, args.store, root, cases)
    plots(report, cases, args.out)
    results_by_kind(report, cases)
    files(report, cases)
    with open(os.path.join(args.out, "report.md"), "w") as f:
        f.write(report.markdown())
    with open(os.path.join(args.out, "report.html"), "w") as f:
        f.write(report.html("rollcheck report"))
    print(f"report: {os.path.join(args.out, 'report.html')}")


if __name__ == "__main__":
    sys.exit(main())

"""The report's findings: what rollcheck found about the preprint, from the
JSON of `rollcheck audit` (the claim table, every mode) and of `rollcheck
robustness` (every headline comparison over the modelling choices). Nothing
is rerun here; every number is read from those two files.

The headline is the cylinder / oloid ratio of each score (above 1: the
oloid's distribution is the more even, as the preprint claims) in four
settings:
  - the preprint: its printed value and the audit's paper-compatible
    recomputation (its code, its meshes);
  - matched resolution: the audit's recomputation at equal face counts;
  - real rolling: the robustness study's contact-time uniformity U_inf on the
    exact surface, its range over the modelling choices;
  - line-contact stress: the robustness study's pressure and damage scores,
    their ranges, and the audit's FEM-SDS (contact mechanics mode).
The robustness study's ratios are first body / second body; they are turned
round when its bodies are (oloid, cylinder).
"""
import math
import re

from rollcheck_store import MissingKey, require

# The audit's claims the headline reads (audit/claims_*.cpp), by their text, and the scores of each.
HEADLINE_CLAIMS = (("CDS cylinder / oloid", ("CDS",)), ("SDS cylinder / oloid", ("SDS",)),
                   ("TDS, WDS_vol, WDS_depth cylinder / oloid (the 46-68x range)", ("TDS", "WDS_vol", "WDS_depth")))
# The robustness study's scores in the headline, with their setting and label.
ROBUST_SCORES = (("contact_time_u", "real rolling", "contact time U_inf"),
                 ("accumulated_pressure_whole", "line-contact stress", "accumulated pressure (SDS template)"),
                 ("peak_to_mean_pressure", "line-contact stress", "peak / mean pressure"),
                 ("basquin_damage_whole", "line-contact stress", "Basquin damage (FDS)"))
SETTINGS = ("the preprint (its code and meshes)", "matched resolution", "real rolling", "line-contact stress")
RATIO = re.compile(r"(\d+(?:\.\d+)?(?:e[-+]?\d+)?)x")


def ratios_in(text):
    """The ratios ('2.4x, 2.8x') in an audit cell's text, in order."""
    return [float(x) for x in RATIO.findall(text)]


def audit_rows(audit):
    """Headline rows from the audit: (setting, score, low, high, source)."""
    claims = {require(c, "claim", "--audit: claims"): c for c in require(audit, "claims", "--audit")}
    rows = []
    for claim, scores in HEADLINE_CLAIMS:
        if claim not in claims:
            raise MissingKey(f"--audit: no claim '{claim}' (the headline reads it)")
        c = claims[claim]
        cells = require(c, "recomputations", f"--audit: claim '{claim}'")
        printed = ratios_in(str(require(c, "paper_value", f"--audit: claim '{claim}'")))
        for k, score in enumerate(scores):
            if k < len(printed):
                rows.append(("the preprint (its code and meshes)", f"{score}, as printed", printed[k], printed[k],
                             "the preprint"))
        for mode, setting in (("paper-compatible", SETTINGS[0]), ("matched resolution", SETTINGS[1])):
            values = ratios_in(cells.get(mode, {}).get("value", ""))
            for score, v in zip(scores, values):
                rows.append((setting, score, v, v, f"audit, {mode} mode"))
        fem = cells.get("contact mechanics", {}).get("value", "")
        if scores == ("SDS",) and ratios_in(fem):
            rows.append((SETTINGS[3], "FEM-SDS (contact mechanics)", ratios_in(fem)[0], ratios_in(fem)[0],
                         "audit, contact mechanics mode"))
    return rows


def robustness_rows(robustness):
    """Headline rows from the robustness study's oloid-cylinder comparisons: their ranges, cylinder / oloid."""
    rows = []
    for k, c in enumerate(require(robustness, "comparisons", "--robustness")):
        at = f"--robustness: comparisons/{k}"
        bodies = require(c, "bodies", at)
        if sorted(bodies) != ["cylinder", "oloid"]:
            continue
        for key, setting, label in ROBUST_SCORES:
            if require(c, "score", at) != key:
                continue
            low, high = (float(require(c, "ratio_min", at)), float(require(c, "ratio_max", at)))
            if bodies[0] == "oloid":
                low, high = 1 / high, 1 / low
            if math.isfinite(low) and math.isfinite(high) and low > 0:
                rows.append((setting, label, low, high, f"robustness: {require(c, 'verdict', at)}"))
    return rows


def span(low, high):
    return f"{low:.3g}x" if low == high else f"{low:.3g}-{high:.3g}x"


def paragraph(rows, audit, robustness):
    """The opening paragraph: what rollcheck found, with the headline's numbers."""
    def first(setting, score):
        return next((r for r in rows if r[0] == setting and r[1] == score), None)
    parts = []
    printed, repro, matched = (first(SETTINGS[0], "CDS, as printed"), first(SETTINGS[0], "CDS"),
                               first(SETTINGS[1], "CDS"))
    if printed and repro and matched:
        parts.append(f"rollcheck reproduces the preprint's headline, a cylinder / oloid CDS of {span(*printed[2:4])}, "
                     f"with the published code on its meshes ({span(*repro[2:4])}), but the two meshes have "
                     f"different face counts and the score falls as about N^-2: at matched resolution the ratio is "
                     f"{span(*matched[2:4])}.")
    rolling = first(SETTINGS[2], "contact time U_inf")
    if rolling:
        verdict = rolling[4].split(": ", 1)[1]
        parts.append(f"Rolling for real on the exact surface, the cylinder / oloid ratio of contact-time uniformity "
                     f"spans {span(*rolling[2:4])} over the modelling choices ({verdict}): "
                     + ("the ranking holds under every choice." if verdict == "robust"
                        else "which body is the more even depends on them."))
    stress = [r for r in rows if r[0] == SETTINGS[3]]
    below = [r for r in stress if r[3] < 1]
    if stress:
        parts.append(f"Under line-contact stress, the ratio is below 1 (the cylinder the more even body) for "
                     f"{len(below)} of {len(stress)} scores: "
                     + "; ".join(f"{r[1]} {span(r[2], r[3])}" for r in stress) + ".")
    if not audit:
        parts.append("The audit's JSON was not given (`rollcheck audit --json PATH`, then `--audit PATH`): the "
                     "preprint's and the matched-resolution ratios are missing.")
    if not robustness:
        parts.append("The robustness study's JSON was not given (`rollcheck robustness --json PATH`, then "
                     "`--robustness PATH`): the ranges over the modelling choices are missing.")
    return " ".join(parts)


def headline(audit, robustness):
    """The headline's rows (setting, score, low, high, source) and its opening paragraph."""
    rows = (audit_rows(audit) if audit else []) + (robustness_rows(robustness) if robustness else [])
    return rows, paragraph(rows, audit, robustness)


def claim_text(audit, claim, modes):
    """'verdict: value (mode); ...' of an audit claim, from the first of `modes` that it has; None without it."""
    for c in require(audit, "claims", "--audit") if audit else []:
        if c["claim"] == claim:
            cells = require(c, "recomputations", f"--audit: claim '{claim}'")
            values = [f"{cells[m]['value']} ({m})" for m in modes if cells.get(m, {}).get("value")]
            verdicts = f"The audit: reproduced: {c['reproduced']['verdict']}, true: {c['true']['verdict']}"
            return f"{verdicts}; " + "; ".join(values) if values else verdicts
    return None


def items(audit, robustness, figures):
    """The findings after the headline, each {title, text, figures, skip}: `figures` maps a plot's name
    (headline, robustness, fem_sds, pressure_profile) to its drawn figures, or to the reason it has none."""
    def item(title, text, plot):
        drawn = figures.get(plot)
        return {"title": title, "text": text, "figures": drawn if isinstance(drawn, list) else [],
                "skip": drawn if isinstance(drawn, str) else None}
    out = [item("The preprint's 58x and the face count",
                "The preprint's scores all weight each face by its area squared, so at a fixed body they fall "
                "as about N^-2 with the face count N, and the preprint's ratio compares its published meshes, whose "
                "face counts differ. "
                + (claim_text(audit, "CDS ∝ N_faces^-2.03", ("paper-compatible",)) or "") + ".", "headline")]
    rolling = [c for c in (robustness or {}).get("comparisons", [])
               if sorted(c["bodies"]) == ["cylinder", "oloid"]]
    if rolling:
        verdicts = "; ".join(f"{c['score']}: {c['verdict']}" for c in rolling)
        out.append(item("The oloid against the cylinder over the modelling choices",
                        f"Over the grid of rolling energy, contact width, load rule and end margin, the oloid "
                        f"against the cylinder: {verdicts}. Below 1 in the figure the oloid is the more even.",
                        "robustness"))
    out.append(item("The SDS's point-Hertz pressures against the FEM's contact pressures",
                    (claim_text(audit, "The SDS's point-Hertz pressures are the contact pressures of the rolling "
                                "bodies", ("corrected physics", "contact mechanics")) or
                     "The bodies touch along a ruling, where line-contact Hertz holds")
                    + ". The FEM solves the line contact; line-contact Hertz is its analytic solution.", "fem_sds"))
    out.append(item("The FEM against Hertz theory",
                    (claim_text(audit, "Hertz analytics valid for a sphere and a cylinder; FEM check of Hertz "
                                "(future work: the preprint's Dirichlet FEM failed)", ("corrected physics",))
                     or "Penalty-contact FEM of a sphere and a cylinder against Hertz") + ".", "pressure_profile"))
    return out

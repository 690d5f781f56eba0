#!/usr/bin/python3
"""Plots a study CSV written by `rollcheck hertz --study convergence|penalty`.

convergence: |relative error| of p0 and of the contact size (a or b) against
wall time, log-log, one curve per model and degree (speed against error).
penalty: the same errors against penalty_c, one curve per model.
pointwise (hertz_pointwise.csv): |relative error| of the largest nodal
pressure and the profile's RMS error against wall time, one curve per model,
degree and pressure recovery.

usage: hertz_study_plot.py STUDY.csv OUT.png   (Debian's /usr/bin/python3)
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    with open(path, newline="") as f:
        return [row for row in csv.DictReader(f) if row["status"] == "ok"]


def curves(rows, key):
    groups = {}
    for row in rows:
        groups.setdefault(key(row), []).append(row)
    return groups


def main(csv_path, png_path):
    rows = read_rows(csv_path)
    penalty = len({row["penalty_c"] for row in rows}) > 1
    pointwise = "pointwise" in csv_path.rsplit("/", 1)[-1]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), constrained_layout=True)
    panels = (((axes[0], "p_max_nodal_error", "largest nodal pressure"),
               (axes[1], "profile_rms_error", "pressure profile (RMS / p0)")) if pointwise else
              ((axes[0], "p0_error", "peak pressure p0"), (axes[1], "size_error", "contact size a or b")))
    for ax, column, label in panels:
        groups = curves(rows, lambda r: f"{r['model']} P{r['degree']}"
                        + (f" {r['pressure_recovery']}" if pointwise else ""))
        x_column, x_label = (("penalty_c", "penalty c (kappa = c E / h)") if penalty
                             else ("wall_s", "wall time (s)"))
        for name, group in sorted(groups.items()):
            group.sort(key=lambda r: float(r[x_column]))
            x = [float(r[x_column]) for r in group]
            y = [max(abs(float(r[column])), 1e-6) for r in group]
            ax.loglog(x, y, "o-", label=name)
        ax.axhline(5e-3 if pointwise else 3e-3, color="grey", lw=0.8, ls="--")
        ax.set_xlabel(x_label)
        ax.set_ylabel(f"|relative error| of {label}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("rollcheck hertz: penalty study" if penalty else
                 "rollcheck hertz: speed against pointwise error" if pointwise else
                 "rollcheck hertz: speed against error")
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

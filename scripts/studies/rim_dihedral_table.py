#!/usr/bin/python3
"""The rims' angles over a loop from `rollcheck rim --body` JSON files
(docs/methods/rims.md#the-rims-angle-section-and-dihedral): for each run the
loop's summary (loaded ends, singular ends, the range of the dihedral
angles, the dihedral's wedge exponent less the section's over every loaded
end) and a Markdown table of its directly modelled ends: section and
dihedral angle, the wedge equation at each, and the FEM's fitted exponent
or end/interior ratio at the modelled (dihedral) angle.

    scripts/studies/rim_dihedral_table.py RUN.json [RUN.json ...]
"""
import json
import sys


def number(value, fmt="{:.3f}"):
    return "-" if value is None else fmt.format(value)


def fem_column(e):
    if e.get("outside_model"):
        return "outside the model"
    if e["singular"]:
        return f"singular, measured {number(e['measured_exponent'])}"
    return f"{number(e['end_to_interior'], '{:.3f}')} ({'converged' if e['converged'] else 'NOT converged'})"


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for path in sys.argv[1:]:
        j = json.load(open(path))
        aware = (j["loop_scores"].get("end_aware") or [{}])[0]
        print(f"{j['body']}, {j['counter_face']}, edge r_e = {j['edge_radius_m']} m: "
              f"{j['loop_scores']['loaded_ends']} loaded ends, {aware.get('singular_ends', '-')} singular; "
              f"section {j['loop_scores']['loaded_end_angle_min_deg']:.1f}-{j['loop_scores']['loaded_end_angle_max_deg']:.1f} deg, "
              f"dihedral {j['loaded_end_dihedral_min_deg']:.1f}-{j['loaded_end_dihedral_max_deg']:.1f} deg; "
              f"dihedral exponent - section exponent: mean {j['dihedral_minus_section_exponent_mean']:.3f}, "
              f"largest {j['dihedral_minus_section_exponent_max']:.3f}; status: {j['end_aware_status']}\n")
        print("| orientation | end | section (deg) | dihedral (deg) | wedge exponent at the section | at the dihedral "
              "| FEM at the dihedral: exponent or end/interior | run time (s) |")
        print("|---|---|---|---|---|---|---|---|")
        for e in j["ends"]:
            print(f"| {e['orientation']} | {e['end']} | {e['interior_angle_deg']:.1f} | {e['dihedral_angle_deg']:.1f}"
                  f"{'' if abs(e['modelled_angle_deg'] - e['dihedral_angle_deg']) < 1e-9 else ' (modelled %.1f)' % e['modelled_angle_deg']}"
                  f" | {e['section_wedge_exponent']:.3f} | {e['dihedral_wedge_exponent']:.3f} | {fem_column(e)}"
                  f" | {e['wall_s']:.0f} |")
        print()


if __name__ == "__main__":
    main()

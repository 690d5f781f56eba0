#pragma once
// Wing of the study layer (study/life): a rounded rim end's pressure
// concentration as the life integrals take it, from the rim study's end
// model (study/rims, fem/scenes/rim_end_contact.h).
//
// A rounded end's peak over line Hertz at the end's q and R depends on the
// edge's boundary layer s / b = 2 r_e / (pi R), far more than on q
// (docs/results/rim-ends.md): with r_e held, doubling R raises it by about
// a quarter, doubling q lowers it by 3 %. So the concentration is read as
// a function of R / r_e alone,
//     rho(R / r_e), linear in ln(R / r_e) between the table's nodes,
// held at its first node below it (R <= r_e: the rounding is the
// surface) and at its last above it (an end sharper than the table's
// last node: reported as outside the table, its rho an underestimate).
// The table is data, not code: cases/life/rounded_end_ratios.json, the
// rim study's converged end models with the commands that made them.
#include <filesystem>
#include <string>
#include <vector>

namespace rollcheck::study::life
{
struct RoundedEndRatios
{
  std::vector<double> r_over_edge_radius;  ///< ascending, from 1
  std::vector<double> end_over_line_hertz; ///< rho at each
  double interior_angle_deg = 0;           ///< of the end models
  std::string source;                      ///< the commands that made them
  /// rho at R / r_e (held at the table's ends).
  double operator()(double r_over_edge_radius) const;
  /// Whether R / r_e lies at or below the table's last node.
  bool covers(double r_over_edge_radius) const;
};

/// The table in `path` (JSON: r_over_edge_radius, end_over_line_hertz,
/// interior_angle_deg, source). InputError naming the file and the key when
/// it is missing, unreadable, or not two or more ascending positive nodes.
RoundedEndRatios read_rounded_end_ratios(const std::filesystem::path& path);

/// cases/life/rounded_end_ratios.json in rollcheck's data folder.
std::filesystem::path default_rounded_end_ratios_path();
} // namespace rollcheck::study::life

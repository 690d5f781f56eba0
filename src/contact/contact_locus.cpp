#include "contact/contact_locus.h"
#include "core/error.h"
#include "oracle/heights.h"
#include <fmt/format.h>

namespace rollcheck::contact
{
namespace
{
/// The lowest vertex of `body` under the rotation whose third row is `row`.
int lowest_vertex(const oracle::RollingBody& body, const Eigen::Vector3d& row)
{
  int lowest = 0;
  double height = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < body.vertices.size(); ++v)
    if (const double h = oracle::height(row, body.vertices, v); h < height)
    {
      height = h;
      lowest = static_cast<int>(v);
    }
  return lowest;
}
} // namespace

ContactLocus contact_locus(std::span<const oracle::Circle> circles, const Eigen::Vector3d& centre_of_mass_m,
                           const oracle::RollingBody& body, const Eigen::Matrix3d& rotation,
                           const LocusSettings& options, const std::vector<int>* oracle_faces)
{
  if (circles.size() < 2)
    throw InputError(fmt::format("contact locus: the body must be the hull of two or more circles, got {}",
                                 circles.size()));
  ContactLocus locus;
  locus.rotation = rotation;
  locus.support = oracle::circle_hull_support_set(circles, rotation, options.support_tolerance);
  const auto& touching = locus.support.circles;
  switch (locus.support.kind)
  {
  case oracle::CircleSupportKind::point:
    locus.creases.push_back(fmt::format("stands on the rim of circle {} (a point of an edge)", touching[0]));
    break;
  case oracle::CircleSupportKind::disc:
  case oracle::CircleSupportKind::polygon:
    locus.creases.push_back(fmt::format("lies on a flat face bounded by the rim of circle {}", touching[0]));
    break;
  case oracle::CircleSupportKind::segment:
  {
    const oracle::TwoCircleBody pair{circles[touching[0]], circles[touching[1]]};
    const Eigen::Vector3d exposed = rotation.transpose() * -Eigen::Vector3d::UnitZ();
    locus.ruling = oracle::ruling_at(pair, exposed);
    const oracle::Ruling& r = *locus.ruling;
    const double c = (centre_of_mass_m - r.start_m).dot(r.axis) / r.length_m;
    locus.centre_of_pressure = c;
    locus.in_equilibrium = c > 0 && c < 1;
    if (!locus.in_equilibrium)
      break;
    locus.loaded_from = c > 2.0 / 3.0 ? 1 - 3 * (1 - c) : 0;
    locus.loaded_to = c < 1.0 / 3.0 ? 3 * c : 1;
    // An end carries load unless the triangle's zero falls exactly on it.
    if (locus.loaded_from == 0 && oracle::line_load(1.0, c, r.length_m, 0.0) > 0)
      locus.creases.push_back(fmt::format("ruling start on the rim of circle {}", touching[0]));
    if (locus.loaded_to == 1 && oracle::line_load(1.0, c, r.length_m, 1.0) > 0)
      locus.creases.push_back(fmt::format("ruling end on the rim of circle {}", touching[1]));
    break;
  }
  }
  if (oracle_faces)
    locus.oracle_faces = *oracle_faces;
  else
  {
    const Eigen::Vector3d row = rotation.row(2).transpose();
    int lowest_face = -1;
    oracle::ground_contacts(body, row, lowest_vertex(body, row), options.ground_at_lowest_centroid,
                            options.contact_threshold_m, locus.oracle_faces, lowest_face);
  }
  return locus;
}

std::vector<int> faces_along_ruling(const oracle::FaceCones& cones, const ContactLocus& locus,
                                    std::span<const double> fractions)
{
  if (!locus.ruling)
    throw ComputationError("faces_along_ruling: the locus has no ruling");
  const oracle::Ruling& r = *locus.ruling;
  std::vector<int> faces;
  int guess = 0;
  for (const double s : fractions)
  {
    guess = oracle::locate_face(cones, r.start_m + s * (r.end_m - r.start_m), guess);
    faces.push_back(guess);
  }
  return faces;
}
} // namespace rollcheck::contact

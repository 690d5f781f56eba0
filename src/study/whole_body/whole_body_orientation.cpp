// The orientations the whole-body check takes (study/whole_body/whole_body_check.h
// WholeBodyOrientation): the ruling nearest a direction, the locus's centre
// of pressure and loaded part, the rims' leans and the loaded ends' q and b.
#include "study/whole_body/whole_body_check.h"
#include "core/degree.h"
#include "contact/hertz.h"
#include "contact/rim_overhang.h"
#include "core/error.h"
#include "oracle/line_load.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/rolling_study.h"
#include "study/whole_body/check_context.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::study::whole_body
{
namespace
{
/// What every orientation of one body shares: its circles and centre of mass.
struct OrientedBody
{
  std::vector<oracle::Circle> circles;
  oracle::TwoCircleBody two;
  Eigen::Vector3d centre_of_mass_m;

  explicit OrientedBody(const geometry::BodySpec& body)
      : circles(oracle::line_contact_circles(body)), two(oracle::two_circle_body(circles)),
        centre_of_mass_m(oracle::mass_model_of_mesh(geometry::make_body(body), 1.0).centre_of_mass_m)
  {
  }
};

WholeBodyOrientation orientation_of(const OrientedBody& body, const WholeBodyCheckSettings& s, double direction_deg)
{
  const std::vector<oracle::Circle>& circles = body.circles;
  const oracle::TwoCircleBody& two = body.two;
  WholeBodyOrientation o;
  o.direction_deg = direction_deg;
  const Eigen::Vector3d hint(std::cos(direction_deg * degree), std::sin(direction_deg * degree), 0.0);
  o.ruling = oracle::ruling_at(two, oracle::contact_curve_point(two, hint));
  const Eigen::Vector3d& G = body.centre_of_mass_m;
  const double L = o.ruling.length_m, c = (G - o.ruling.start_m).dot(o.ruling.axis) / L;
  o.centre_of_pressure = c;
  o.centre_of_mass_height_m = (o.ruling.start_m - G).dot(o.ruling.direction);
  o.rim_overhang_rad = contact::rim_overhang(circles, 0, 1, o.ruling);
  // c within 1e-9 of an end (the preprint's body at direction 0, where its
  // sheet's radius at the other end is unbounded): balanced on a point.
  o.in_equilibrium = c > 1e-9 && c < 1 - 1e-9;
  if (!o.in_equilibrium)
    return o;
  o.loaded_from = c < 1.0 / 3 ? 0.0 : c > 2.0 / 3 ? 1 - 3 * (1 - c) : 0.0;
  o.loaded_to = c < 1.0 / 3 ? 3 * c : 1.0;
  const double E_star = contact::effective_modulus(s.youngs_modulus_pa, s.poisson_ratio, false);
  for (int e = 0; e < 2; ++e)
    if (const double q = oracle::line_load(s.normal_load_n, c, L, e); q > 0)
    {
      o.end_load_n_per_m[e] = q;
      // R rounds to about -1e-19 m at an apex (the oloid's vertex): b = 0 there.
      o.end_half_width_m[e] = line_half_width(q, std::max(o.radius_m(e), 0.0), E_star);
    }
  return o;
}
} // namespace

double WholeBodyOrientation::interior_angle_deg(int end) const
{
  return 90 + rim_overhang_rad[static_cast<std::size_t>(end)] / degree;
}

WholeBodyOrientation whole_body_orientation(const WholeBodyCheckSettings& s, double direction_deg)
{
  return orientation_of(OrientedBody(s.body), s, direction_deg);
}

std::vector<WholeBodyOrientation> scan_whole_body_orientations(const WholeBodyCheckSettings& s, double step_deg)
{
  if (!(step_deg > 0 && step_deg <= 360))
    throw InputError(fmt::format("scan step {} deg: must lie in (0, 360]", step_deg));
  const OrientedBody body(s.body);
  std::vector<WholeBodyOrientation> scan;
  for (int k = 0; k * step_deg < 360 - 1e-9; ++k)
    scan.push_back(orientation_of(body, s, k * step_deg));
  return scan;
}
} // namespace rollcheck::study::whole_body

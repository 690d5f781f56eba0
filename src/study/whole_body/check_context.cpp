// What the stages of one whole-body check share (study/whole_body/check_context.h).
#include "study/whole_body/check_context.h"
#include "contact/hertz.h"
#include "fem/load_control.h"
#include "fem/petsc_session.h"
#include "geometry/body.h"
#include "geometry/convex_ray.h"
#include "oracle/line_load.h"
#include "study/loop_scores/fem_sds.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::study::whole_body
{
namespace
{
/// The whole body's sizes from the locus's b at the stations and the loaded
/// ends (check_context.h).
BodySizing body_sizing(const CheckContext& context)
{
  const WholeBodyCheckSettings& s = context.settings;
  BodySizing sizing;
  double smallest_b = INFINITY, largest_b = 0;
  std::vector<double> sized_at = context.fractions;
  sized_at.insert(sized_at.end(), context.end_fractions.begin(), context.end_fractions.end());
  for (const double f : sized_at)
    if (const double q = context.locus_load_at(f); q > 0)
    {
      const double b = context.half_width_at(q, f);
      smallest_b = std::min(smallest_b, b);
      largest_b = std::max(largest_b, b);
    }
  // The locus's b at the loaded ends (0 where the locus leaves an end
  // unloaded).
  double smallest_end_b = INFINITY;
  for (const double b : context.orientation.end_half_width_m)
    if (b > 0)
      smallest_end_b = std::min(smallest_end_b, b);
  if (!std::isfinite(smallest_end_b))
    smallest_end_b = smallest_b;
  sizing.smallest_b = smallest_b;
  sizing.largest_b = largest_b;
  sizing.smallest_end_b = smallest_end_b;
  fem::WholeBodySizes& sizes = sizing.sizes;
  sizes.contact_m = smallest_b / s.contact_elements;
  sizes.strip_half_width_m = s.strip_over_half_width * largest_b;
  sizes.growth = s.section_growth;
  sizes.far_m = s.body.radius_m / 8;
  sizes.layer_growth = s.layer_growth;
  sizes.largest_layer_m = context.length_m() / s.layers_across_length;
  sizes.end_layer_m = s.body_end_layer * smallest_end_b;
  if (!s.end_layers_only)
  {
    sizes.edge_m = sizes.end_layer_m;
    sizes.edge_zone_m = s.end_zone_over_half_width * largest_b;
  }
  return sizing;
}
} // namespace

double line_half_width(double q, double R, double E_star) { return std::sqrt(4 * q * R / (std::numbers::pi * E_star)); }

CheckContext::CheckContext(MPI_Comm comm, const WholeBodyCheckSettings& settings,
                           const WholeBodyOrientation& orientation)
    : comm(comm), settings(settings), orientation(orientation),
      effective_modulus_pa(contact::effective_modulus(settings.youngs_modulus_pa, settings.poisson_ratio, false)),
      log(fem::world_rank() == 0),
      fractions(loop_scores::slice_fractions(orientation.loaded_from, orientation.loaded_to, settings.end_margin,
                                             settings.stations)),
      end_fractions{orientation.loaded_from, orientation.loaded_to}
{
  sizing = body_sizing(*this);
  if (settings.body.body != "cylinder")
    pose = mapped_pose(*this);
}

double CheckContext::radius_at(double f) const
{
  return (1 - f) * orientation.ruling.start_radius_m + f * orientation.ruling.end_radius_m;
}

double CheckContext::locus_load_at(double f) const
{
  return oracle::line_load(settings.normal_load_n, centre_of_pressure(), length_m(), f);
}

fem::MappedBodyPose mapped_pose(const CheckContext& context)
{
  const WholeBodyCheckSettings& s = context.settings;
  const oracle::Ruling& ruling = context.orientation.ruling;
  const Eigen::Vector3d ex = ruling.axis, ez = -ruling.direction, ey = ez.cross(ex);
  geometry::SurfaceMesh body = geometry::make_body(s.body);
  for (Eigen::Index i = 0; i < body.vertices.rows(); ++i)
  {
    const Eigen::Vector3d p = body.vertices.row(i).transpose() - ruling.start_m;
    body.vertices.row(i) = Eigen::RowVector3d(p.dot(ex), p.dot(ey), p.dot(ez));
  }
  auto hull = std::make_shared<const geometry::HalfSpaces>(geometry::half_spaces(body));
  fem::MappedBodyPose pose;
  pose.length_m = ruling.length_m;
  pose.cut_height_m = context.orientation.centre_of_mass_height_m;
  pose.reference_radius_m = s.body.radius_m;
  pose.radius_m = {ruling.start_radius_m, ruling.end_radius_m};
  pose.end_overhang_rad = context.orientation.rim_overhang_rad;
  pose.end_zone_m = s.end_margin * ruling.length_m;
  pose.chord = [hull](const Eigen::Vector3d& p, const Eigen::Vector3d& d) { return geometry::line_chord(*hull, p, d); };
  return pose;
}

RigidStart rigid_start(const CheckContext& context, double load_at_centre)
{
  const double c = context.centre_of_pressure(), R = context.radius_at(c);
  const double b = context.half_width_at(load_at_centre, c);
  const fem::LineApproach estimate = fem::line_contact_approach(load_at_centre, R, b, context.effective_modulus_pa);
  return RigidStart{estimate.approach_m, estimate.exponent, 0.5 * b * b / R};
}

BodySolve solve_body(const CheckContext& context, const fem::WholeBodySizes& sizes, double load_at_centre)
{
  const WholeBodyCheckSettings& s = context.settings;
  const WholeBodyOrientation& o = context.orientation;
  const double L = context.length_m(), c = context.centre_of_pressure();
  const fem::WholeBodyMesh mesh
      = context.pose ? fem::build_mapped_body_mesh(context.comm, *context.pose, sizes)
                     : fem::build_cylinder_body_mesh(context.comm, {s.body.radius_m, L, o.centre_of_mass_height_m}, sizes);
  if (context.log)
    spdlog::info("whole-body mesh: {} node planes, {} nodes per section, contact elements {:.3g} m (b / {:.3g}), "
                 "end layers {:.3g} m, gmsh {:.1f} s",
                 mesh.planes_m.size(), mesh.section_nodes, sizes.contact_m,
                 context.half_width_at(load_at_centre, c) / sizes.contact_m, sizes.end_layer_m, mesh.gmsh_s);
  fem::WholeBodyLoad load;
  load.force_n = s.normal_load_n;
  load.centre_of_mass_along_m = c * L;
  load.youngs_modulus_pa = s.youngs_modulus_pa;
  load.poisson_ratio = s.poisson_ratio;
  load.penalty_c = s.penalty_c;
  load.contact_element_m = sizes.contact_m;
  const RigidStart rigid = rigid_start(context, load_at_centre);
  load.first_approach_m = rigid.approach_m;
  load.approach_exponent = rigid.exponent;
  load.first_shift_m = rigid.shift_m;
  load.edge_half_width_m = 0.5 * context.sizing.smallest_end_b;
  return BodySolve{fem::solve_whole_body(context.comm, mesh, load), mesh.planes_m.size(), mesh.section_nodes,
                   mesh.gmsh_s};
}
} // namespace rollcheck::study::whole_body

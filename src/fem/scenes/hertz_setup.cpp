#include "fem/scenes/hertz_setup.h"
#include "contact/hertz.h"
#include "core/error.h"
#include "fem/field_output.h"
#include <cmath>
#include <utility>
#include <fmt/format.h>

namespace rollcheck::fem
{
int default_refine(Model model, int degree)
{
  // Elements across the contact radius: 10 * 2^(refine / 2); see
  // hertz_setup.h and the convergence table in the README.
  switch (model)
  {
  case Model::axisymmetric: return degree == 1 ? 4 : 2;
  case Model::plane_strain: return degree == 1 ? 4 : 2;
  case Model::solid: return degree == 1 ? 2 : 0;
  }
  return 0;
}

HertzSettings with_model_defaults(HertzSettings s)
{
  const bool solid = s.model == Model::solid;
  if (s.degree == 0)
    s.degree = solid ? 2 : 1;
  const bool pointwise = solid && s.degree == 2;
  for (int* levels : {&s.pole_refine, &s.edge_refine})
    if (*levels == -1)
      *levels = pointwise ? 2 : 0;
  if (s.contact_cap == ContactCapMesh::automatic)
    s.contact_cap = pointwise ? ContactCapMesh::rings : ContactCapMesh::unstructured;
  if (s.pressure_recovery == PressureRecovery::automatic)
    s.pressure_recovery = pointwise ? PressureRecovery::touching : PressureRecovery::lumped;
  return s;
}

std::string recovery_name(PressureRecovery recovery)
{
  switch (recovery)
  {
  case PressureRecovery::automatic: return "auto";
  case PressureRecovery::lumped: return "lumped";
  case PressureRecovery::consistent: return "consistent";
  case PressureRecovery::penalty: return "penalty";
  case PressureRecovery::touching: return "touching";
  }
  return "lumped";
}

std::string contact_cap_name(ContactCapMesh cap)
{
  switch (cap)
  {
  case ContactCapMesh::automatic: return "auto";
  case ContactCapMesh::unstructured: return "unstructured";
  case ContactCapMesh::rings: return "rings";
  }
  return "unstructured";
}

void validate(const HertzSettings& s)
{
  auto positive = [](double value, const char* what) {
    if (!std::isfinite(value) || value <= 0)
      throw InputError(fmt::format("hertz: {} must be positive and finite, got {}", what, value));
  };
  positive(s.radius_m, "radius_m (--radius)");
  positive(s.youngs_modulus_pa, "youngs_modulus_pa (--youngs-modulus)");
  positive(s.force_n, "force_n (--load)");
  positive(s.length_m, "length_m (--length)");
  positive(s.penalty_c, "penalty_c (--penalty-c)");
  positive(s.force_rtol, "force_rtol (--force-rtol)");
  if (!std::isfinite(s.poisson_ratio) || s.poisson_ratio <= -1.0 || s.poisson_ratio >= 0.5)
    throw InputError(fmt::format("hertz: poisson_ratio (--poisson) must lie in (-1, 0.5), got {}", s.poisson_ratio));
  if (s.degree < 0 || s.degree > 2)
    throw InputError(fmt::format("hertz: degree (--degree) must be 1 or 2 (0: the model's default), got {}", s.degree));
  if (s.refine > 12)
    throw InputError(fmt::format("hertz: refine (--refine) must be at most 12, got {}", s.refine));
  for (const auto& [levels, what] : {std::pair{s.pole_refine, "pole_refine (--pole-refine)"},
                                     std::pair{s.edge_refine, "edge_refine (--edge-refine)"}})
  {
    if (levels < -1 || levels > 6)
      throw InputError(fmt::format("hertz: {} must lie in 0..6 (-1: the model's default), got {}", what, levels));
    if (levels > 0 && s.model != Model::solid)
      throw InputError(fmt::format("hertz: {} refines the 3d model's contact; the {} model has none", what,
                                   model_name(s.model)));
  }
  if (s.contact_cap == ContactCapMesh::rings && s.model != Model::solid)
    throw InputError(fmt::format("hertz: contact_cap (--contact-cap) rings meshes the 3d model's contact cap; the {} "
                                 "model has none",
                                 model_name(s.model)));
  if (!std::isfinite(s.contact_element_size_m) || s.contact_element_size_m < 0)
    throw InputError(fmt::format("hertz: contact_element_size_m (--contact-element-size) must be >= 0, got {}",
                                 s.contact_element_size_m));
  if (s.contact_element_size_m >= s.radius_m / 4)
    throw InputError(fmt::format("hertz: contact_element_size_m {} m is not small against the radius {} m",
                                 s.contact_element_size_m, s.radius_m));
  if (s.force_rtol >= 0.01)
    throw InputError(fmt::format("hertz: force_rtol must be below 0.01, got {}", s.force_rtol));
  if (!s.xdmf_path.empty())
  {
    check_field_output(s.xdmf_path, "hertz: the field output (--xdmf)");
  }
}

namespace
{
/// The peak pressure and the subsurface maxima of point or line Hertz.
template <class Hertz>
void take_peak_and_subsurface(HertzReference& r, const Hertz& h)
{
  r.peak_pressure_pa = h.peak_pressure_pa;
  r.max_shear_pa = h.max_shear_pa;
  r.max_shear_depth_m = h.max_shear_depth_m;
  r.max_von_mises_pa = h.max_von_mises_pa;
  r.max_von_mises_depth_m = h.max_von_mises_depth_m;
}
} // namespace

HertzReference hertz_reference(const HertzSettings& s)
{
  const double E = s.youngs_modulus_pa, nu = s.poisson_ratio;
  HertzReference r{};
  r.effective_modulus_pa = contact::effective_modulus(E, nu, s.elastic_plane);
  // Against a rigid plane the body alone supplies E*: E_body / (1 - nu^2) = E*.
  r.body_modulus_pa = r.effective_modulus_pa * (1 - nu * nu);
  if (s.model == Model::plane_strain)
  {
    r.load = s.force_n / s.length_m;
    const contact::LineHertz h = contact::line_contact(r.load, s.radius_m, r.effective_modulus_pa, nu);
    r.contact_size_m = h.half_width_m;
    take_peak_and_subsurface(r, h);
  }
  else
  {
    r.load = s.force_n;
    const contact::PointHertz h = contact::point_contact(r.load, s.radius_m, r.effective_modulus_pa, nu);
    r.contact_size_m = h.contact_radius_m;
    r.approach_m = h.approach_m;
    take_peak_and_subsurface(r, h);
  }
  return r;
}

MeshGrading mesh_grading(const HertzSettings& s, const HertzReference& ref)
{
  const int refine = s.refine >= 0 ? s.refine : default_refine(s.model, s.degree);
  return contact_grading(ref.contact_size_m,
                         s.contact_element_size_m > 0 ? s.contact_element_size_m
                                                      : contact_element_size(ref.contact_size_m, refine),
                         s.radius_m);
}

ContactRefinement contact_refinement(const HertzSettings& s, const HertzReference& ref, const MeshGrading& g)
{
  ContactRefinement r;
  if (s.model != Model::solid)
    return r;
  const double c_H = ref.contact_size_m;
  const auto finer = [&](int levels) { return g.contact_size_m / std::pow(2.0, levels / 2.0); };
  // The ball holds the nodes whose pressure is within 3 % of p0 (s < 0.25
  // c_H), where the largest nodal pressure is found; the tube the nodes
  // whose patches straddle the edge at the grading's h_c = c_H / 10.
  constexpr double pole_radius = 0.25, edge_half_width = 0.1;
  if (s.pole_refine > 0)
  {
    r.pole_size_m = finer(s.pole_refine);
    r.pole_radius_m = pole_radius * c_H;
  }
  if (s.edge_refine > 0)
  {
    r.edge_size_m = finer(s.edge_refine);
    r.edge_half_width_m = edge_half_width * c_H;
    r.edge_radius_m = c_H;
  }
  // The cap reaches beyond the profile (s < 1.5 c_H) and the fine ball; its
  // rings are spaced as the finer of the pole's and the edge's refinement,
  // the edge rings' segments the grading's h_c (fem/mesh/cap_rings.h).
  constexpr double cap_radius = 2.0;
  if (s.contact_cap == ContactCapMesh::rings)
    r.cap = cap_rings({.edge_radius_m = c_H,
                       .spacing_m = finer(std::max(s.pole_refine, s.edge_refine)),
                       .far_spacing_m = g.contact_size_m,
                       .edge_segment_m = g.contact_size_m,
                       .cap_radius_m = cap_radius * c_H,
                       .growth = g.growth});
  return r;
}

} // namespace rollcheck::fem

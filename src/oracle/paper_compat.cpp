#include "oracle/paper_compat.h"
#include "core/comma_list.h"
#include "core/error.h"
#include <fmt/format.h>

namespace rollcheck::oracle
{
PaperCompat PaperCompat::corrected()
{
  PaperCompat c;
  for (const Quirk& q : quirks())
    c.*q.flag = false;
  return c;
}

const std::vector<Quirk>& quirks()
{
  static const std::vector<Quirk> table = {
      {"ground_at_lowest_centroid", &PaperCompat::ground_at_lowest_centroid, "oracle",
       "grounds the body by its lowest face centroid; faces with centroid height < eps above it touch",
       "the plane touches the lowest vertex; heights are measured from it"},
      {"rotate_about_surface_centroid", &PaperCompat::rotate_about_surface_centroid, "oracle",
       "turns the body about trimesh's area-weighted surface centroid and applies gravity there",
       "gravity acts at the centre of mass, the point the free body turns about"},
      {"unit_mass_with_density_one_inertia", &PaperCompat::unit_mass_with_density_one_inertia, "oracle",
       "gravity with a typed-in m = 1 kg, inertia tensor for density 1 (mass = volume)",
       "inertia scaled to the same mass: I m / V"},
      {"body_inertia_in_world_equations", &PaperCompat::body_inertia_in_world_equations, "oracle",
       "body-frame inertia tensor used unrotated with world-frame torque and angular velocity",
       "world-frame inertia R I R^T (and its inverse R I^-1 R^T)"},
      {"centroidal_inertia_for_support_torque", &PaperCompat::centroidal_inertia_for_support_torque, "oracle",
       "gravity torque about the support point divided by the inertia about the centroid",
       "inertia about the support point, I + m (|r|^2 1 - r r^T), r from the support to the centre of mass"},
      {"post_step_angular_velocity", &PaperCompat::post_step_angular_velocity, "oracle",
       "pairs the orientation before a step with the angular velocity after it",
       "angular velocity at the same instant as the orientation"},
      {"identical_bodies_modulus", &PaperCompat::identical_bodies_modulus, "contact",
       "E* = E / (2 (1 - nu^2)), the modulus of two identical bodies, labelled 'vs rigid plane'",
       "E* = E / (1 - nu^2) for an elastic body on a rigid plane"},
      {"doubled_mean_curvature", &PaperCompat::doubled_mean_curvature, "contact",
       "vertex H = |L| / (2 A) = kappa1 + kappa2; kappa = H +- sqrt(H^2 - K) with that doubled H",
       "H = |L| / (4 A), the mean curvature"},
      {"barycentric_vertex_area", &PaperCompat::barycentric_vertex_area, "contact",
       "vertex area a third of each incident face (called 'Voronoi area')",
       "mixed Voronoi area (Meyer et al. 2003)"},
      {"face_curvature_vertex_mean", &PaperCompat::face_curvature_vertex_mean, "contact",
       "face H and K are the plain mean of the three vertex densities",
       "area-weighted mean: sum(A_v H_v) / sum(A_v), i.e. integrated curvature over area"},
      {"sliding_velocity_about_body_origin", &PaperCompat::sliding_velocity_about_body_origin, "contact",
       "v = horizontal part of omega x r, r = face centroid from the body origin (x, y) and from the lowest "
       "centroid (z)",
       "velocity of the face relative to the support point, omega x (c_f - s), horizontal part"},
      {"peak_pressure_as_stress_amplitude", &PaperCompat::peak_pressure_as_stress_amplitude, "contact",
       "Basquin stress amplitude = Hertz peak pressure p0",
       "a zero-to-p0 pulsating cycle has amplitude p0 / 2"},
      {"wear_depth_per_face_area", &PaperCompat::wear_depth_per_face_area, "contact",
       "k p v dt / H summed as 'volume' and divided by the face area as 'depth'",
       "k p v dt / H is the Archard depth; volume = depth x Hertz contact area pi a^2"},
  };
  return table;
}

void apply_quirk_settings(PaperCompat& compat, std::string_view settings, std::string_view origin)
{
  for (const std::string_view item : comma_list_items(settings))
  {
    const std::size_t eq = item.find('=');
    const std::string_view name = item.substr(0, eq);
    const std::string_view value = eq == std::string_view::npos ? std::string_view() : item.substr(eq + 1);
    const Quirk* quirk = nullptr;
    for (const Quirk& q : quirks())
      if (q.name == name)
        quirk = &q;
    if (!quirk)
    {
      std::string known;
      for (const Quirk& q : quirks())
        known += (known.empty() ? "" : ", ") + std::string(q.name);
      throw InputError(fmt::format("{}: unknown quirk '{}' (known: {})", origin, name, known));
    }
    if (value != "paper" && value != "corrected")
      throw InputError(fmt::format("{}: quirk '{}' must be set to 'paper' or 'corrected', got '{}'", origin, name,
                                   value));
    compat.*quirk->flag = value == "paper";
  }
}

std::string describe(const PaperCompat& compat)
{
  std::string out;
  for (const Quirk& q : quirks())
    out += fmt::format("{}{}={}", out.empty() ? "" : ",", q.name, compat.*q.flag ? "paper" : "corrected");
  return out;
}
} // namespace rollcheck::oracle

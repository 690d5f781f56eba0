#pragma once
// The reference code's departures from the physics the preprint describes, one
// named switch each. `true` reproduces the reference code
// (gyapaganda-a11y/substrate-geometry); `false` takes the physically right
// form. PaperCompat::reference() is the paper-compatible mode (every switch
// on), PaperCompat::corrected() turns every switch off. Each switch is
// described, with what the reference does and what is right, in quirks().
//
// Oracle-layer switches change the trajectory or the contact detection;
// contact-layer switches change only how a trajectory is scored.
#include <string>
#include <string_view>
#include <vector>

namespace rollcheck::oracle
{
struct PaperCompat
{
  // --- kinematics and contact detection (oracle layer) ---
  /// Contact is measured from the lowest face centroid, not from the ground
  /// plane through the lowest vertex.
  bool ground_at_lowest_centroid = true;
  /// The body turns about its area-weighted surface centroid (trimesh's
  /// `centroid`), and gravity acts there, instead of at the centre of mass.
  bool rotate_about_surface_centroid = true;
  /// Gravity uses a typed-in mass of 1 kg while the inertia tensor is that of
  /// density 1 (mass = volume in m^3), so the two disagree.
  bool unit_mass_with_density_one_inertia = true;
  /// The body-frame inertia tensor is used, unrotated, in Euler's equations
  /// written with world-frame torque and angular velocity.
  bool body_inertia_in_world_equations = true;
  /// The gravity torque is taken about the support point but divided by the
  /// inertia about the centroid (the contact reaction is left out).
  bool centroidal_inertia_for_support_torque = true;
  /// The angular velocity paired with a sampled orientation is the one after
  /// that step's update (one step later than the orientation).
  bool post_step_angular_velocity = true;

  // --- contact physics (contact layer) ---
  /// E* = E / (2 (1 - nu^2)), the two-identical-bodies modulus, for a body on
  /// a rigid plane.
  bool identical_bodies_modulus = true;
  /// The vertex "mean curvature" is |L| / (2 A) = kappa1 + kappa2, twice H,
  /// and the principal curvatures are then formed as H' +- sqrt(H'^2 - K).
  bool doubled_mean_curvature = true;
  /// Vertex areas are barycentric (a third of each incident face).
  bool barycentric_vertex_area = true;
  /// Face curvatures are the plain mean of the three vertex curvature densities.
  bool face_curvature_vertex_mean = true;
  /// The sliding speed is the horizontal part of omega x r with r the face
  /// centroid from the body origin (x, y) and from the lowest centroid (z).
  bool sliding_velocity_about_body_origin = true;
  /// The Basquin stress amplitude is the full Hertz peak pressure.
  bool peak_pressure_as_stress_amplitude = true;
  /// Archard: k p v dt / H (a depth) is summed as a "wear volume", and divided
  /// by the face area as a "wear depth".
  bool wear_depth_per_face_area = true;

  static PaperCompat reference() { return {}; }
  static PaperCompat corrected();
};

struct Quirk
{
  std::string_view name;
  bool PaperCompat::*flag;
  std::string_view layer;            ///< "oracle" or "contact"
  std::string_view reference_does;
  std::string_view physically_right;
};

/// Every switch, in declaration order.
const std::vector<Quirk>& quirks();

/// Sets switches from "name=paper|corrected,name=...", InputError naming
/// `origin` for an unknown name or value.
void apply_quirk_settings(PaperCompat& compat, std::string_view settings, std::string_view origin);

/// "name=paper|corrected" for every switch, comma-separated.
std::string describe(const PaperCompat& compat);
} // namespace rollcheck::oracle

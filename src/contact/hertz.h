#pragma once
// Classical Hertz theory for an elastic body on a plane (K. L. Johnson,
// Contact Mechanics, CUP 1985, ch. 4). Forces in N, lengths in m, stresses in Pa.
//
// Point contact (sphere of radius R, total force F):
//   a = (3 F R / (4 E*))^(1/3),  p0 = 3 F / (2 pi a^2),  delta = a^2 / R.
// Line contact (cylinder of radius R, force per unit length P):
//   b = sqrt(4 P R / (pi E*)),   p0 = 2 P / (pi b).
// Subsurface stresses along the axis of symmetry (Johnson eqs. 3.45 and 4.49),
// whose maxima are found numerically: for nu = 0.3, tau_max ~ 0.31 p0 at
// z ~ 0.48 a (point) and 0.30 p0 at z ~ 0.79 b (line).
namespace rollcheck::contact
{
/// E* of an elastic body (E, nu) against a rigid plane: E / (1 - nu^2).
double effective_modulus_rigid_plane(double youngs_modulus_pa, double poisson_ratio);
/// E* of two identical elastic bodies: E / (2 (1 - nu^2)) (the preprint's choice).
double effective_modulus_identical_bodies(double youngs_modulus_pa, double poisson_ratio);
/// The first against a rigid plane, the second with `elastic_plane`.
double effective_modulus(double youngs_modulus_pa, double poisson_ratio, bool elastic_plane);

struct PointHertz
{
  double contact_radius_m;
  double peak_pressure_pa;
  double mean_pressure_pa;
  double approach_m;
  double max_shear_pa;          ///< max of the principal shear stress, on the axis
  double max_shear_depth_m;
  double max_von_mises_pa;      ///< max von Mises stress on the axis
  double max_von_mises_depth_m;
};

/// `poisson_ratio` is that of the elastic body, used only for the subsurface stresses.
PointHertz point_contact(double force_n, double radius_m, double effective_modulus_pa, double poisson_ratio);

struct LineHertz
{
  double half_width_m;
  double peak_pressure_pa;
  double mean_pressure_pa;
  double max_shear_pa;
  double max_shear_depth_m;
  double max_von_mises_pa;      ///< plane strain: sigma_y = nu (sigma_x + sigma_z)
  double max_von_mises_depth_m;
};

LineHertz line_contact(double force_per_length_n_per_m, double radius_m, double effective_modulus_pa,
                       double poisson_ratio);

/// Hertz pressure at distance s from the centre of a contact of size c:
/// p0 sqrt(1 - (s/c)^2) inside, 0 outside (same form for point and line).
double pressure_profile(double peak_pressure_pa, double contact_size_m, double s_m);
} // namespace rollcheck::contact

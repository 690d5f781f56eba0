#pragma once
// The subsurface stress field of frictionless line (2D Hertz) contact in
// closed form: McEwen's expressions (E. McEwen, Phil. Mag. 40, 1949; K. L.
// Johnson, "Contact Mechanics", CUP 1985, section 4.3, eq. 4.50). With the
// half-width b, the peak pressure p0, x along the rolling direction from the
// contact's centre and z the depth into the body, all lengths over b:
//     A = 1 - x^2 + z^2,  D = sqrt(A^2 + 4 x^2 z^2),
//     m = sqrt((D + A) / 2) >= 0,  n = sign(x) sqrt((D - A) / 2),
//     sigma_x / p0 = -(m (1 + (z^2 + n^2) / (m^2 + n^2)) - 2 z),
//     sigma_z / p0 = -m (1 - (z^2 + n^2) / (m^2 + n^2)),
//     tau_xz  / p0 = -n (m^2 - z^2) / (m^2 + n^2),
// and, in plane strain, sigma_y = nu (sigma_x + sigma_z). Compressive
// stresses are negative; tau_xz has the sign of the Boussinesq-Flamant
// integral of the Hertz pressure (Johnson eq. 2.23), with which the unit
// tests compare it. Landmarks: the largest in-plane principal shear
// 0.300 p0 at z = 0.786 b on the axis; the orthogonal shear tau_xz reaches
// +-0.250 p0 at z = 0.5 b, x = -+0.87 b.
namespace rollcheck::contact
{
/// Stress over p0 at one point; components in (x, y, z), y along the ruling.
struct LineContactStress
{
  double xx = 0, yy = 0, zz = 0, xz = 0;
  /// In-plane principal shear sqrt(((sigma_x - sigma_z) / 2)^2 + tau_xz^2).
  double in_plane_shear() const;
  /// Mean stress (sigma_x + sigma_y + sigma_z) / 3.
  double hydrostatic() const { return (xx + yy + zz) / 3; }
};

/// The field at (x / b, z / b), z / b >= 0; InputError for a negative depth.
LineContactStress line_contact_subsurface_stress(double x_over_b, double z_over_b, double poisson_ratio);
} // namespace rollcheck::contact

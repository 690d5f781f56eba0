#pragma once
// Element sizes of a scene mesh graded towards a contact of size c: h_c in a
// ball about the first point of contact, growing linearly beyond it; and the
// 1D spacing a structured mesh is graded by.
#include <vector>

namespace rollcheck::fem
{
/// Element sizes of the scene mesh: h_c in the contact zone (a ball of radius
/// fine_radius_m about the first point of contact), growing linearly with
/// the distance beyond it at `growth` m/m up to far_size_m.
struct MeshGrading
{
  double contact_size_m;
  double fine_radius_m;
  double growth;
  double far_size_m;
};
/// h_c = contact_size / (10 * 2^(refine / 2)): refine 0 puts 10 elements
/// across the contact size, each step a factor sqrt(2) more.
double contact_element_size(double contact_size_m, int refine);
/// The grading every scene uses about a contact of size c with contact
/// elements h_c, in a body of size R (see mesh_grading's comments).
MeshGrading contact_grading(double contact_size_m, double contact_element_m, double body_size_m);
/// Nodes from 0 to `length`, spaced h(d) = min(h_max, h_0 + growth max(0,
/// d - fine)) at the distance d from 0; a last gap under half its size is
/// merged into the one before.
std::vector<double> graded_nodes(double length, double h_0, double fine, double growth, double h_max);
} // namespace rollcheck::fem

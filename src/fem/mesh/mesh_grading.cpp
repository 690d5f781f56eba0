#include "fem/mesh/mesh_grading.h"
#include <algorithm>
#include <cmath>

namespace rollcheck::fem
{
double contact_element_size(double contact_size_m, int refine)
{
  return contact_size_m / (10.0 * std::pow(2.0, refine / 2.0));
}

MeshGrading contact_grading(double contact_size_m, double contact_element_m, double body_size_m)
{
  MeshGrading g{};
  g.contact_size_m = contact_element_m;
  // The fine ball covers the contact (radius c_H) with a margin for the
  // penalty's smearing of the edge, and the depth of the subsurface maxima
  // (0.48 a, 0.79 b).
  g.fine_radius_m = std::max(1.25 * contact_size_m, 2 * g.contact_size_m);
  // Sizes grow by 25 % of the distance: about 1 / 0.25 * ln(h_far / h_c)
  // element layers from the contact zone to the far field.
  g.growth = 0.25;
  g.far_size_m = body_size_m / 5;
  return g;
}

std::vector<double> graded_nodes(double length, double h_0, double fine, double growth, double h_max)
{
  std::vector<double> nodes{0.0};
  while (nodes.back() < length)
  {
    const double d = nodes.back();
    nodes.push_back(d + std::min(h_max, h_0 + growth * std::max(0.0, d - fine)));
  }
  if (nodes.size() > 2 && length - nodes[nodes.size() - 2] < 0.5 * (nodes.back() - nodes[nodes.size() - 2]))
    nodes.pop_back();
  nodes.back() = length;
  return nodes;
}
} // namespace rollcheck::fem

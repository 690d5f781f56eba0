#include "geometry/internal_angles.h"
#include <algorithm>
#include <cmath>

namespace rollcheck::geometry
{
namespace
{
// a . b with products accumulated by fused multiply-adds in index order: the
// rounding of the BLAS ddot the reference's numpy calls.
double dot(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::fma(a[2], b[2], std::fma(a[1], b[1], a[0] * b[0]));
}

double norm(const Eigen::Vector3d& a) { return std::sqrt(dot(a, a)); }

// numpy's cross: each component is one product minus another, rounded apart.
Eigen::Vector3d cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double clamped_cosine(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double la, double lb)
{
  return std::clamp(dot(a, b) / (la * lb + 1e-30), -1.0, 1.0);
}
} // namespace

InternalAngles internal_angles(const SurfaceMesh& mesh)
{
  const Eigen::Index n = mesh.faces.rows();
  InternalAngles out;
  out.cosines.setZero(n, 3);
  out.angles.setZero(n, 3);
  out.areas.setZero(n);
  out.degenerate.assign(n, false);
  constexpr double min_doubled_area = 1e-15; // m^2, the reference's cut-off
  for (Eigen::Index f = 0; f < n; ++f)
  {
    const Eigen::Vector3d vi = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::Vector3d vj = mesh.vertices.row(mesh.faces(f, 1));
    const Eigen::Vector3d vk = mesh.vertices.row(mesh.faces(f, 2));
    const Eigen::Vector3d eij = vj - vi, eik = vk - vi, ejk = vk - vj;
    const double doubled_area = norm(cross(eij, eik));
    if (doubled_area < min_doubled_area)
    {
      out.degenerate[f] = true;
      continue;
    }
    out.areas[f] = 0.5 * doubled_area;
    const double lij = norm(eij), lik = norm(eik), ljk = norm(ejk);
    out.cosines(f, 0) = clamped_cosine(eij, eik, lij, lik);
    out.cosines(f, 1) = clamped_cosine(-eij, ejk, lij, ljk);
    out.cosines(f, 2) = clamped_cosine(-eik, -ejk, lik, ljk);
    for (int c = 0; c < 3; ++c)
      out.angles(f, c) = std::acos(out.cosines(f, c));
  }
  return out;
}
} // namespace rollcheck::geometry

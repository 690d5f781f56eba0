#include "geometry/mass_properties.h"
#include "geometry/face_areas.h"
#include "geometry/face_centroids.h"
#include <Eigen/Geometry>

namespace rollcheck::geometry
{
MassProperties mass_properties(const SurfaceMesh& mesh)
{
  // Integrals over the solid of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx, summed
  // face by face from the divergence theorem (Eberly 2002, "subexpressions").
  Eigen::Matrix<double, 10, 1> integral = Eigen::Matrix<double, 10, 1>::Zero();
  auto subexpressions = [](double w0, double w1, double w2, double& f1, double& f2, double& f3, double& g0,
                           double& g1, double& g2) {
    const double temp0 = w0 + w1;
    f1 = temp0 + w2;
    const double temp1 = w0 * w0;
    const double temp2 = temp1 + w1 * temp0;
    f2 = temp2 + w2 * f1;
    f3 = w0 * temp1 + w1 * temp2 + w2 * f2;
    g0 = f2 + w0 * (f1 + w0);
    g1 = f2 + w1 * (f1 + w1);
    g2 = f2 + w2 * (f1 + w2);
  };
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    const Eigen::Vector3d p0 = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::Vector3d p1 = mesh.vertices.row(mesh.faces(f, 1));
    const Eigen::Vector3d p2 = mesh.vertices.row(mesh.faces(f, 2));
    const Eigen::Vector3d d = (p1 - p0).cross(p2 - p0);
    double f1x, f2x, f3x, g0x, g1x, g2x, f1y, f2y, f3y, g0y, g1y, g2y, f1z, f2z, f3z, g0z, g1z, g2z;
    subexpressions(p0.x(), p1.x(), p2.x(), f1x, f2x, f3x, g0x, g1x, g2x);
    subexpressions(p0.y(), p1.y(), p2.y(), f1y, f2y, f3y, g0y, g1y, g2y);
    subexpressions(p0.z(), p1.z(), p2.z(), f1z, f2z, f3z, g0z, g1z, g2z);
    integral[0] += d.x() * f1x;
    integral[1] += d.x() * f2x;
    integral[2] += d.y() * f2y;
    integral[3] += d.z() * f2z;
    integral[4] += d.x() * f3x;
    integral[5] += d.y() * f3y;
    integral[6] += d.z() * f3z;
    integral[7] += d.x() * (p0.y() * g0x + p1.y() * g1x + p2.y() * g2x);
    integral[8] += d.y() * (p0.z() * g0y + p1.z() * g1y + p2.z() * g2y);
    integral[9] += d.z() * (p0.x() * g0z + p1.x() * g1z + p2.x() * g2z);
  }
  const double scale[10] = {1.0 / 6, 1.0 / 24, 1.0 / 24, 1.0 / 24, 1.0 / 60,
                            1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
  for (int i = 0; i < 10; ++i)
    integral[i] *= scale[i];

  MassProperties props;
  props.volume_m3 = integral[0];
  props.centre_of_mass = Eigen::Vector3d(integral[1], integral[2], integral[3]) / props.volume_m3;
  const Eigen::Vector3d& c = props.centre_of_mass;
  const double m = props.volume_m3;
  // Second moments about the centre of mass (parallel-axis theorem).
  const double xx = integral[4] - m * c.x() * c.x();
  const double yy = integral[5] - m * c.y() * c.y();
  const double zz = integral[6] - m * c.z() * c.z();
  const double xy = integral[7] - m * c.x() * c.y();
  const double yz = integral[8] - m * c.y() * c.z();
  const double zx = integral[9] - m * c.z() * c.x();
  props.inertia << yy + zz, -xy, -zx, -xy, xx + zz, -yz, -zx, -yz, xx + yy;

  const Eigen::VectorXd areas = face_areas(mesh);
  props.area_m2 = areas.sum();
  props.surface_centroid = (face_centroids(mesh).transpose() * areas) / props.area_m2;
  return props;
}
} // namespace rollcheck::geometry

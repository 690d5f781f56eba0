#pragma once
// Mass properties of a closed, outward-oriented triangle surface by the
// divergence theorem: each face spans a tetrahedron with the origin, whose
// signed volume integrals of 1, x, x x^T are summed exactly
// (D. Eberly, "Polyhedral Mass Properties (Revisited)", 2002).
#include "geometry/surface_mesh.h"
#include <Eigen/Core>

namespace rollcheck::geometry
{
struct MassProperties
{
  double area_m2;                   ///< sum of face areas
  double volume_m3;                 ///< enclosed volume
  Eigen::Vector3d centre_of_mass;   ///< of the solid, uniform density (m)
  Eigen::Vector3d surface_centroid; ///< area-weighted mean of face centroids (m)
  Eigen::Matrix3d inertia;          ///< about the centre of mass, density 1 kg/m^3 (kg m^2)
};

MassProperties mass_properties(const SurfaceMesh& mesh);
} // namespace rollcheck::geometry

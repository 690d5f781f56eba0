#pragma once
// A closed triangle surface: vertex positions (m) and faces (vertex indices,
// counter-clockwise seen from outside, so that face normals point outward).
#include <Eigen/Core>

namespace rollcheck::geometry
{
using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Faces = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct SurfaceMesh
{
  Vertices vertices;
  Faces faces;
};
} // namespace rollcheck::geometry

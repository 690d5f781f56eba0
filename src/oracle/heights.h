#pragma once
// Heights of points under a rotation and the faces touching the ground: the
// inner loops of both oracles. A height is the third row r of the rotation
// applied to a point p, accumulated as fma(r2, p_z, fma(r1, p_y, r0 p_x)):
// the rounding of the OpenBLAS dgemm behind the reference's `R @ points.T`, so
// that contact decisions at the threshold agree with it to the last bit where
// the inputs do.
//
// ground_contacts() finds the faces whose centroid lies less than eps above
// the ground without computing every height in double precision: the lowest
// face centroid is no higher than u, the lowest centroid of the faces around
// the support vertex and than the previous orientation's lowest face (or,
// grounded at the vertex, the ground is the vertex's height u); a single-precision pass over all centroids keeps those with
// h < u + eps + tol, tol = 1e-5 of the body size far above the
// single-precision error (about 1e-6 of it); only they get exact heights. The
// result is identical to computing all heights exactly. Loops run eight
// centroids at a time with AVX2 and FMA when the processor has them.
#include "oracle/rolling_body.h"
#include <Eigen/Core>
#include <vector>

namespace rollcheck::oracle
{
/// r . p_i with the rounding described above.
double height(const Eigen::Vector3d& row, const PointSet& points, std::size_t i);

/// Heights of the points listed in `index` into `out`.
void heights_of(const Eigen::Vector3d& row, const PointSet& points, const int* index, std::size_t n, double* out);

/// R p_i, each row with the rounding described above.
Eigen::Vector3d rotate(const Eigen::Matrix3d& rotation, const PointSet& points, std::size_t i);

/// Appends to `out`, in increasing order, every face f with
/// (h_f - ground) < threshold, where h_f is the height of its centroid under
/// `row` (the third row of the rotation) and ground is the lowest centroid
/// height (`ground_at_lowest_centroid`, as the reference code) or the height
/// of `support_vertex`, the lowest vertex. Returns the ground height.
/// `lowest_face` is a face expected near the bottom (the previous call's
/// lowest, -1 if none), used only to tighten the bound; it is updated to this
/// orientation's lowest candidate face.
double ground_contacts(const RollingBody& body, const Eigen::Vector3d& row, int support_vertex,
                       bool ground_at_lowest_centroid, double threshold, std::vector<int>& out, int& lowest_face);
} // namespace rollcheck::oracle

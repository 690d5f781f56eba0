#pragma once
// The lowest vertex of a convex body under a rotation, as numpy.argmin picks
// it from all vertex heights (the first index among exact ties), found by a
// steepest-descent walk on the vertex graph from the previous support vertex.
// On a convex polytope a vertex lower than all its neighbours is the lowest of
// all (the body lies in the cone of its edges). The walk's answer is used only
// when every neighbour is higher by more than a tolerance far above rounding
// (1e-9 of the body size); otherwise (ties, as at the identity orientation of a
// cylinder, or a vertex not on any face) all vertices are scanned.
#include "oracle/rolling_body.h"
#include <Eigen/Core>

namespace rollcheck::oracle
{
class SupportSearch
{
public:
  explicit SupportSearch(const RollingBody& body);
  /// Index of the lowest vertex under `row` (third row of the rotation).
  int lowest(const Eigen::Vector3d& row);
  /// Full scans made so far (for tests and benchmarks).
  long scans() const { return scans_; }

private:
  const RollingBody* body_;
  int current_ = 0;
  double tie_tolerance_;
  long scans_ = 0;
};
} // namespace rollcheck::oracle

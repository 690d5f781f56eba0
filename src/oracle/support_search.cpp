#include "oracle/support_search.h"
#include "oracle/heights.h"
#include <iterator>
#include <limits>

namespace rollcheck::oracle
{
SupportSearch::SupportSearch(const RollingBody& body) : body_(&body), tie_tolerance_(1e-9 * body.size_m) {}

int SupportSearch::lowest(const Eigen::Vector3d& row)
{
  const PointSet& v = body_->vertices;
  if (body_->every_vertex_on_a_face)
  {
    int at = current_;
    double h = height(row, v, static_cast<std::size_t>(at));
    double neighbour_h[64];
    for (;;)
    {
      const int first = body_->neighbour_offsets[at];
      const auto degree = static_cast<std::size_t>(body_->neighbour_offsets[at + 1] - first);
      if (degree > std::size(neighbour_h))
        break; // an unusual vertex: scan everything below
      heights_of(row, v, body_->neighbours.data() + first, degree, neighbour_h);
      int next = at;
      double lowest_h = h, second_h = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < degree; ++k)
      {
        if (neighbour_h[k] < lowest_h)
        {
          second_h = lowest_h;
          next = body_->neighbours[first + static_cast<int>(k)];
          lowest_h = neighbour_h[k];
        }
        else
          second_h = std::min(second_h, neighbour_h[k]);
      }
      if (next == at)
      {
        // A local minimum: the answer unless a neighbour is within the tie
        // tolerance of it.
        if (second_h - h > tie_tolerance_)
        {
          current_ = at;
          return at;
        }
        break;
      }
      at = next;
      h = lowest_h;
    }
  }
  ++scans_;
  int best = 0;
  double best_h = height(row, v, 0);
  for (std::size_t i = 1; i < v.size(); ++i)
    if (const double hi = height(row, v, i); hi < best_h)
    {
      best = static_cast<int>(i);
      best_h = hi;
    }
  current_ = best;
  return best;
}
} // namespace rollcheck::oracle

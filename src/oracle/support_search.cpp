#include "oracle/support_search.h"
#include "oracle/heights.h"

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
    for (;;)
    {
      int next = at;
      double lowest_h = h;
      for (int k = body_->neighbour_offsets[at]; k < body_->neighbour_offsets[at + 1]; ++k)
      {
        const int n = body_->neighbours[k];
        const double hn = height(row, v, static_cast<std::size_t>(n));
        if (hn < lowest_h)
        {
          next = n;
          lowest_h = hn;
        }
      }
      if (next == at)
        break;
      at = next;
      h = lowest_h;
    }
    bool clear = true;
    for (int k = body_->neighbour_offsets[at]; k < body_->neighbour_offsets[at + 1] && clear; ++k)
      clear = height(row, v, static_cast<std::size_t>(body_->neighbours[k])) - h > tie_tolerance_;
    if (clear)
    {
      current_ = at;
      return at;
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

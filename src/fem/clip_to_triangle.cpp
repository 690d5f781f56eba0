#include "fem/clip_to_triangle.h"
#include <utility>

namespace rollcheck::fem
{
double cross(const Point2& o, const Point2& a, const Point2& b)
{
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

std::array<double, 3> barycentric(const std::array<Point2, 3>& t, const Point2& q)
{
  const double area = cross(t[0], t[1], t[2]);
  const double w1 = cross(t[0], q, t[2]) / area, w2 = cross(t[0], t[1], q) / area;
  return {1 - w1 - w2, w1, w2};
}

std::vector<Point2> clip_to_triangle(std::vector<Point2> subject, std::array<Point2, 3> clip)
{
  if (cross(clip[0], clip[1], clip[2]) < 0)
    std::swap(clip[1], clip[2]); // counter-clockwise: inside is left of each edge
  for (int e = 0; e < 3 && !subject.empty(); ++e)
  {
    const Point2& a = clip[e];
    const Point2& b = clip[(e + 1) % 3];
    std::vector<Point2> kept;
    for (std::size_t i = 0; i < subject.size(); ++i)
    {
      const Point2& p = subject[i];
      const Point2& q = subject[(i + 1) % subject.size()];
      const double sp = cross(a, b, p), sq = cross(a, b, q);
      if (sp >= 0)
        kept.push_back(p);
      if ((sp >= 0) != (sq >= 0))
      {
        const double t = sp / (sp - sq);
        kept.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
    subject = std::move(kept);
  }
  return subject;
}
} // namespace rollcheck::fem

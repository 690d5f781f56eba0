#include "oracle/approximate_oracle.h"
#include "core/error.h"
#include "oracle/heights.h"
#include "oracle/support_search.h"
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::oracle
{
void validate(const ApproximateSettings& o)
{
  if (o.steps < 1)
    throw InputError(fmt::format("approximate oracle: steps must be at least 1, got {}", o.steps));
  if (!std::isfinite(o.contact_threshold_m) || o.contact_threshold_m < 0)
    throw InputError(fmt::format("approximate oracle: contact threshold must be finite and >= 0, got {} m",
                                 o.contact_threshold_m));
  if (!std::isfinite(o.roll_cycles) || !std::isfinite(o.wobble_amplitude_rad))
    throw InputError("approximate oracle: roll cycles and wobble amplitude must be finite");
}

Eigen::Matrix3d approximate_rotation(long step, const ApproximateSettings& o)
{
  constexpr double pi = std::numbers::pi;
  const auto t = static_cast<double>(step), n = static_cast<double>(o.steps);
  // Evaluated in the reference's order of operations.
  const double beta = t * (2 * pi / n) * o.roll_cycles;
  const double alpha = std::sin(t * pi / n) * o.wobble_amplitude_rad;
  const double cb = std::cos(beta), sb = std::sin(beta), ca = std::cos(alpha), sa = std::sin(alpha);
  // R_x(alpha) R_y(beta): every entry is a single product, so its rounding
  // does not depend on how the matrix product is summed.
  Eigen::Matrix3d r;
  r << cb, 0.0, sb, sa * sb, ca, -sa * cb, -ca * sb, sa, ca * cb;
  return r;
}

Trajectory approximate_oracle(const RollingBody& body, const ApproximateSettings& options, const PaperCompat& compat)
{
  validate(options);
  Trajectory out;
  out.contact_threshold_m = options.contact_threshold_m;
  out.samples.reserve(static_cast<std::size_t>(options.steps));
  out.contact_offsets.reserve(static_cast<std::size_t>(options.steps) + 1);
  SupportSearch support(body);
  int lowest_face = -1;
  for (long t = 0; t < options.steps; ++t)
  {
    const Eigen::Matrix3d r = approximate_rotation(t, options);
    const Eigen::Vector3d row = r.row(2).transpose();
    const int s = support.lowest(row);
    const double ground = ground_contacts(body, row, s, compat.ground_at_lowest_centroid, options.contact_threshold_m,
                                          out.contact_faces, lowest_face);
    out.contact_offsets.push_back(static_cast<int>(out.contact_faces.size()));
    out.samples.push_back({r, Eigen::Vector3d::Zero(), s, ground, 0});
    if (t == 0) // room for every step's contacts, judged by the first
      out.contact_faces.reserve(2 * out.contact_faces.size() * static_cast<std::size_t>(options.steps) + 64);
  }
  return out;
}
} // namespace rollcheck::oracle

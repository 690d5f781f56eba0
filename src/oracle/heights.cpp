#include "oracle/heights.h"
#include <cmath>
#include <immintrin.h>
#include <limits>

namespace rollcheck::oracle
{
namespace
{
bool has_avx2_fma()
{
  static const bool available = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return available;
}

double height_portable(const double* r, double x, double y, double z) { return std::fma(r[2], z, std::fma(r[1], y, r[0] * x)); }

// The same expression; with the target's FMA enabled std::fma is one instruction.
__attribute__((target("avx2,fma"))) double height_fma(const double* r, double x, double y, double z)
{
  return std::fma(r[2], z, std::fma(r[1], y, r[0] * x));
}

// For each 8-bit mask, the lanes that are set, packed to the front.
struct PackTable
{
  int lanes[256][8];
  constexpr PackTable() : lanes()
  {
    for (int mask = 0; mask < 256; ++mask)
    {
      int k = 0;
      for (int lane = 0; lane < 8; ++lane)
        if (mask & (1 << lane))
          lanes[mask][k++] = lane;
    }
  }
};
constexpr PackTable pack_table;

/// Indices with single-precision height below `bound`; returns how many.
std::size_t below_portable(const RollingBody& b, const float* r, float bound, int* out)
{
  std::size_t count = 0;
  for (std::size_t i = 0; i < b.centroid_x.size(); ++i)
    if (std::fma(r[2], b.centroid_z[i], std::fma(r[1], b.centroid_y[i], r[0] * b.centroid_x[i])) < bound)
      out[count++] = static_cast<int>(i);
  return count;
}

// A group of eight with any passing writes eight indices and advances by the
// number that passed, so `out` needs seven entries of slack.
__attribute__((target("avx2,fma"))) std::size_t below_avx2(const RollingBody& b, const float* r, float bound, int* out)
{
  const float *x = b.centroid_x.data(), *y = b.centroid_y.data(), *z = b.centroid_z.data();
  const std::size_t n = b.centroid_x.size();
  const __m256 r0 = _mm256_set1_ps(r[0]), r1 = _mm256_set1_ps(r[1]), r2 = _mm256_set1_ps(r[2]);
  const __m256 limit = _mm256_set1_ps(bound);
  std::size_t count = 0, i = 0;
  for (; i + 8 <= n; i += 8)
  {
    const __m256 h = _mm256_fmadd_ps(r2, _mm256_loadu_ps(z + i),
                                     _mm256_fmadd_ps(r1, _mm256_loadu_ps(y + i), _mm256_mul_ps(r0, _mm256_loadu_ps(x + i))));
    const int mask = _mm256_movemask_ps(_mm256_cmp_ps(h, limit, _CMP_LT_OQ));
    // Contacting faces come in runs of nearby indices (hull facets are
    // created region by region), so most groups pass nothing and the branch
    // predicts well.
    if (mask == 0)
      continue;
    const __m256i lanes = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(pack_table.lanes[mask]));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + count),
                        _mm256_add_epi32(lanes, _mm256_set1_epi32(static_cast<int>(i))));
    count += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
  }
  for (; i < n; ++i)
    if (std::fma(r[2], z[i], std::fma(r[1], y[i], r[0] * x[i])) < bound)
      out[count++] = static_cast<int>(i);
  return count;
}
/// Exact heights of the listed points.
void heights_portable(const double* r, const PointSet& p, const int* index, std::size_t n, double* out)
{
  for (std::size_t k = 0; k < n; ++k)
  {
    const auto i = static_cast<std::size_t>(index[k]);
    out[k] = height_portable(r, p.x[i], p.y[i], p.z[i]);
  }
}

__attribute__((target("avx2,fma"))) void heights_fma(const double* r, const PointSet& p, const int* index,
                                                     std::size_t n, double* out)
{
  for (std::size_t k = 0; k < n; ++k)
  {
    const auto i = static_cast<std::size_t>(index[k]);
    out[k] = std::fma(r[2], p.z[i], std::fma(r[1], p.y[i], r[0] * p.x[i]));
  }
}
} // namespace

double height(const Eigen::Vector3d& row, const PointSet& points, std::size_t i)
{
  return has_avx2_fma() ? height_fma(row.data(), points.x[i], points.y[i], points.z[i])
                        : height_portable(row.data(), points.x[i], points.y[i], points.z[i]);
}

void heights_of(const Eigen::Vector3d& row, const PointSet& points, const int* index, std::size_t n, double* out)
{
  (has_avx2_fma() ? heights_fma : heights_portable)(row.data(), points, index, n, out);
}

Eigen::Vector3d rotate(const Eigen::Matrix3d& rotation, const PointSet& points, std::size_t i)
{
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rows = rotation;
  auto f = has_avx2_fma() ? height_fma : height_portable;
  return {f(rows.data(), points.x[i], points.y[i], points.z[i]), f(rows.data() + 3, points.x[i], points.y[i], points.z[i]),
          f(rows.data() + 6, points.x[i], points.y[i], points.z[i])};
}

double ground_contacts(const RollingBody& body, const Eigen::Vector3d& row, int support_vertex,
                       bool ground_at_lowest_centroid, double threshold, std::vector<int>& out, int& lowest_face)
{
  const auto s = static_cast<std::size_t>(support_vertex);
  const int first = body.face_offsets[s], last = body.face_offsets[s + 1];
  // Upper bound of the ground: the lowest of the centroids around the support
  // vertex and the previous lowest face, or the support vertex itself.
  double ground_bound = std::numeric_limits<double>::infinity();
  if (ground_at_lowest_centroid)
  {
    if (lowest_face >= 0)
      ground_bound = height(row, body.centroids, static_cast<std::size_t>(lowest_face));
    double around[64];
    for (int k = first; k < last; k += 64)
    {
      const auto n = static_cast<std::size_t>(std::min(last - k, 64));
      heights_of(row, body.centroids, body.faces_around.data() + k, n, around);
      for (std::size_t j = 0; j < n; ++j)
        ground_bound = std::min(ground_bound, around[j]);
    }
  }
  else
    ground_bound = height(row, body.vertices, s);

  thread_local std::vector<int> candidates;
  if (candidates.size() < body.centroids.size() + 8)
    candidates.resize(body.centroids.size() + 8);
  std::size_t n_candidates = 0;
  if (std::isfinite(ground_bound) && std::isfinite(threshold))
  {
    const double limit = ground_bound + threshold + 1e-5 * body.size_m;
    float bound = static_cast<float>(limit);
    if (static_cast<double>(bound) < limit)
      bound = std::nextafter(bound, std::numeric_limits<float>::infinity());
    const float r[3] = {static_cast<float>(row[0]), static_cast<float>(row[1]), static_cast<float>(row[2])};
    n_candidates = has_avx2_fma() ? below_avx2(body, r, bound, candidates.data())
                                  : below_portable(body, r, bound, candidates.data());
  }
  else // no faces around the support vertex, or an infinite threshold: every face is a candidate
    for (std::size_t f = 0; f < body.centroids.size(); ++f)
      candidates[n_candidates++] = static_cast<int>(f);

  thread_local std::vector<double> heights;
  heights.resize(n_candidates);
  heights_of(row, body.centroids, candidates.data(), n_candidates, heights.data());
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n_candidates; ++k)
  {
    if (heights[k] < lowest)
    {
      lowest = heights[k];
      lowest_face = candidates[k];
    }
  }
  const double ground = ground_at_lowest_centroid ? lowest : height(row, body.vertices, s);
  std::size_t kept = 0;
  for (std::size_t k = 0; k < n_candidates; ++k)
  {
    candidates[kept] = candidates[k];
    kept += heights[k] - ground < threshold;
  }
  out.insert(out.end(), candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(kept));
  return ground;
}
} // namespace rollcheck::oracle

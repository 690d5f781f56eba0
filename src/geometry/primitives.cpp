#include "geometry/primitives.h"
#include "core/error.h"
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <numbers>
#include <vector>

namespace rollcheck::geometry
{
namespace
{
void require_size(double value, const char* body, const char* name)
{
  if (!std::isfinite(value) || value <= 0)
    throw InputError(fmt::format("{}: {} must be positive and finite, got {}", body, name, value));
}

void require_count(int value, int minimum, const char* body, const char* name)
{
  if (value < minimum)
    throw InputError(fmt::format("{}: {} must be at least {}, got {}", body, name, minimum, value));
}

SurfaceMesh from_lists(const std::vector<std::array<double, 3>>& v, const std::vector<std::array<int, 3>>& f)
{
  SurfaceMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(v.size()), 3);
  mesh.faces.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t i = 0; i < v.size(); ++i)
    mesh.vertices.row(static_cast<Eigen::Index>(i)) << v[i][0], v[i][1], v[i][2];
  for (std::size_t i = 0; i < f.size(); ++i)
    mesh.faces.row(static_cast<Eigen::Index>(i)) << f[i][0], f[i][1], f[i][2];
  return mesh;
}

/// Sphere-like body from latitude rings between polar angles [0, phi_max]:
/// a pole vertex, n_lat rings, and (when phi_max < pi) a flat cap fanned from
/// a centre vertex; phi_max = pi closes it with the opposite pole.
SurfaceMesh latitude_body(double r, int n_lat, int n_lon, double phi_max)
{
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<int, 3>> f;
  const bool full = phi_max >= std::numbers::pi;
  v.push_back({0, 0, -r}); // south pole: the hemisphere rests on it
  const int rings = full ? n_lat - 1 : n_lat;
  for (int i = 1; i <= rings; ++i)
  {
    const double phi = phi_max * i / n_lat;
    for (int j = 0; j < n_lon; ++j)
    {
      const double lambda = 2 * std::numbers::pi * j / n_lon;
      v.push_back({r * std::sin(phi) * std::cos(lambda), r * std::sin(phi) * std::sin(lambda), -r * std::cos(phi)});
    }
  }
  auto ring = [n_lon](int i, int j) { return 1 + (i - 1) * n_lon + (j % n_lon); };
  for (int j = 0; j < n_lon; ++j)
    f.push_back({0, ring(1, j + 1), ring(1, j)});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < n_lon; ++j)
    {
      f.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
      f.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
    }
  const int top = static_cast<int>(v.size());
  v.push_back(full ? std::array<double, 3>{0, 0, r} : std::array<double, 3>{0, 0, -r * std::cos(phi_max)});
  for (int j = 0; j < n_lon; ++j)
    f.push_back({top, ring(rings, j), ring(rings, j + 1)});
  return from_lists(v, f);
}
} // namespace

SurfaceMesh cylinder(double radius, double height, int sections)
{
  require_size(radius, "cylinder", "radius (m)");
  require_size(height, "cylinder", "height (m)");
  require_count(sections, 3, "cylinder", "sections");
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<int, 3>> f;
  for (double z : {-height / 2, height / 2})
    for (int j = 0; j < sections; ++j)
    {
      const double t = 2 * std::numbers::pi * j / sections;
      v.push_back({radius * std::cos(t), radius * std::sin(t), z});
    }
  const int bottom_centre = static_cast<int>(v.size());
  v.push_back({0, 0, -height / 2});
  v.push_back({0, 0, height / 2});
  const int top_centre = bottom_centre + 1;
  for (int j = 0; j < sections; ++j)
  {
    const int a = j, b = (j + 1) % sections;
    f.push_back({a, b, sections + b});
    f.push_back({a, sections + b, sections + a});
    f.push_back({bottom_centre, b, a});
    f.push_back({top_centre, sections + a, sections + b});
  }
  return from_lists(v, f);
}

SurfaceMesh icosphere(double radius, int subdivisions)
{
  require_size(radius, "icosphere", "radius (m)");
  if (subdivisions < 0 || subdivisions > 8)
    throw InputError(fmt::format("icosphere: subdivisions must lie in 0..8, got {}", subdivisions));
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  auto project = [radius](std::array<double, 3> p) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return std::array<double, 3>{radius * p[0] / n, radius * p[1] / n, radius * p[2] / n};
  };
  for (auto& p : v)
    p = project(p);
  for (int level = 0; level < subdivisions; ++level)
  {
    std::map<std::pair<int, int>, int> midpoint;
    auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = midpoint.find(key); it != midpoint.end())
        return it->second;
      v.push_back(project({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2}));
      return midpoint[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : f)
    {
      const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    f = std::move(finer);
  }
  return from_lists(v, f);
}

SurfaceMesh uv_sphere(double radius, int n_lat, int n_lon)
{
  require_size(radius, "UV sphere", "radius (m)");
  require_count(n_lat, 2, "UV sphere", "latitude bands");
  require_count(n_lon, 3, "UV sphere", "longitude sectors");
  return latitude_body(radius, n_lat, n_lon, std::numbers::pi);
}

SurfaceMesh hemisphere(double radius, int n_lat, int n_lon)
{
  require_size(radius, "hemisphere", "radius (m)");
  require_count(n_lat, 1, "hemisphere", "latitude bands");
  require_count(n_lon, 3, "hemisphere", "longitude sectors");
  return latitude_body(radius, n_lat, n_lon, std::numbers::pi / 2);
}
} // namespace rollcheck::geometry

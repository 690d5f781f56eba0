#include "oracle/contact_density.h"
#include "core/error.h"
#include "geometry/face_areas.h"
#include "geometry/mass_properties.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <fmt/format.h>
#include <initializer_list>
#include <map>
#include <numbers>
#include <vector>

namespace rollcheck::oracle
{
namespace
{
/// A polygon in the barycentric coordinates of a clipped triangle (or the
/// parameter of a clipped segment, with the third coordinate unused). Each
/// clip by a half-plane adds at most one corner, so the three clips of a cone
/// leave at most 6; held in place, since the oracles clip millions of them
/// (on the heap, their allocations were a fifth of a rolling optimisation's
/// time: perf on `optimize --oracle rolling`).
class Polygon
{
public:
  Polygon() = default;
  Polygon(std::initializer_list<Eigen::Vector3d> corners)
  {
    for (const Eigen::Vector3d& c : corners)
      push_back(c);
  }
  void push_back(const Eigen::Vector3d& corner)
  {
    if (size_ == capacity)
      throw ComputationError("contact density: a clipped polygon has more than 8 corners");
    corners_[size_++] = corner;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const Eigen::Vector3d& operator[](std::size_t i) const { return corners_[i]; }
  const Eigen::Vector3d* begin() const { return corners_.data(); }
  const Eigen::Vector3d* end() const { return corners_.data() + size_; }

private:
  static constexpr std::size_t capacity = 8;
  std::array<Eigen::Vector3d, capacity> corners_;
  std::size_t size_ = 0;
};

/// Sutherland-Hodgman: keeps the part of `polygon` where the linear function
/// with values `g` at the three reference corners is non-negative.
Polygon clip(const Polygon& polygon, const Eigen::Vector3d& g)
{
  Polygon out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector3d& p = polygon[i];
    const Eigen::Vector3d& q = polygon[(i + 1) % n];
    const double gp = g.dot(p), gq = g.dot(q);
    if (gp >= 0)
      out.push_back(p);
    if ((gp >= 0) != (gq >= 0))
      out.push_back(p + (q - p) * (gp / (gp - gq)));
  }
  return out;
}

/// Share of the reference triangle covered by a polygon in barycentric coordinates.
double triangle_share(const Polygon& polygon)
{
  double twice_area = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Eigen::Vector3d& p = polygon[i];
    const Eigen::Vector3d& q = polygon[(i + 1) % polygon.size()];
    twice_area += p[1] * q[2] - p[2] * q[1];
  }
  return std::abs(twice_area); // the reference triangle has twice-area 1
}

/// Share of the reference segment [0, 1] (coordinates (1 - t, t, 0)) kept by a polygon of 2 points.
double segment_share(const Polygon& polygon)
{
  if (polygon.size() < 2)
    return 0;
  double lo = 1, hi = 0;
  for (const auto& p : polygon)
    lo = std::min(lo, p[1]), hi = std::max(hi, p[1]);
  return std::max(0.0, hi - lo);
}

class Accumulator
{
public:
  Accumulator(const FaceCones& cones, Eigen::VectorXd& measure, long& fallbacks)
      : cones_(cones), measure_(measure), fallbacks_(fallbacks), stamp_(static_cast<std::size_t>(cones.faces.rows()), -1)
  {
  }

  /// Distributes `weight` over the cones met by the triangle (or, if `segment`,
  /// the segment X0 X1) uniformly in its parameters. Points relative to O.
  void add(const std::array<Eigen::Vector3d, 3>& x, double weight, bool segment)
  {
    if (!(weight > 0))
      return;
    ++serial_;
    const Polygon reference = segment ? Polygon{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)}
                                      : Polygon{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                                Eigen::Vector3d(0, 0, 1)};
    const Eigen::Vector3d centre = segment ? Eigen::Vector3d((x[0] + x[1]) / 2) : Eigen::Vector3d((x[0] + x[1] + x[2]) / 3);
    guess_ = locate_face(cones_, centre + cones_.centre_m, guess_);
    shares_.clear();
    double total = 0;
    std::deque<int> queue{guess_};
    stamp_[static_cast<std::size_t>(guess_)] = serial_;
    while (!queue.empty())
    {
      const int f = queue.front();
      queue.pop_front();
      const double share = share_in(f, x, reference, segment);
      if (!(share > 0))
        continue;
      shares_.emplace_back(f, share);
      total += share;
      for (int k = 0; k < 3; ++k)
      {
        const int n = cones_.neighbours(f, k);
        if (stamp_[static_cast<std::size_t>(n)] != serial_)
        {
          stamp_[static_cast<std::size_t>(n)] = serial_;
          queue.push_back(n);
        }
      }
    }
    if (total < 1 - 1e-9)
    {
      // The walk was cut (the element meets a cone only at a corner): scan all faces.
      ++fallbacks_;
      shares_.clear();
      total = 0;
      for (int f = 0; f < cones_.faces.rows(); ++f)
        if (const double share = share_in(f, x, reference, segment); share > 0)
        {
          shares_.emplace_back(f, share);
          total += share;
        }
    }
    if (!(total > 0))
      throw ComputationError("contact density: a contact element lies in no face's cone");
    // Elements lying on a cone boundary are shared; normalising splits them evenly.
    for (const auto& [f, share] : shares_)
      measure_[f] += weight * share / total;
  }

private:
  double share_in(int f, const std::array<Eigen::Vector3d, 3>& x, const Polygon& reference, bool segment) const
  {
    Polygon polygon = reference;
    for (int k = 0; k < 3 && !polygon.empty(); ++k)
    {
      const Eigen::Vector3d normal = cones_.planes.row(f).segment<3>(3 * k).transpose();
      const Eigen::Vector3d g(normal.dot(x[0]), normal.dot(x[1]), segment ? 0.0 : normal.dot(x[2]));
      polygon = clip(polygon, g);
    }
    return segment ? segment_share(polygon) : (polygon.size() < 3 ? 0.0 : triangle_share(polygon));
  }

  const FaceCones& cones_;
  Eigen::VectorXd& measure_;
  long& fallbacks_;
  std::vector<int> stamp_;
  int serial_ = 0;
  int guess_ = 0;
  std::vector<std::pair<int, double>> shares_;
};
} // namespace

geometry::SurfaceMesh subdivide_faces(const geometry::SurfaceMesh& mesh, int parts)
{
  if (parts < 1)
    throw InputError(fmt::format("subdivide faces: parts must be at least 1, got {}", parts));
  if (parts == 1)
    return mesh;
  std::vector<Eigen::Vector3d> points;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    points.emplace_back(mesh.vertices.row(v).transpose());
  // Interior points of each undirected edge, listed from its lower to its higher vertex index.
  std::map<std::pair<int, int>, int> first_edge_point;
  auto edge_point = [&](int a, int b, int k) { // k-th of parts - 1 points going from a to b
    const bool forward = a < b;
    const auto key = forward ? std::pair{a, b} : std::pair{b, a};
    auto [it, inserted] = first_edge_point.emplace(key, static_cast<int>(points.size()));
    if (inserted)
      for (int j = 1; j < parts; ++j)
        points.push_back(points[key.first] + (points[key.second] - points[key.first]) * (double(j) / parts));
    return it->second + (forward ? k - 1 : parts - 1 - k);
  };
  std::vector<std::array<int, 3>> triangles;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    const int a = mesh.faces(f, 0), b = mesh.faces(f, 1), c = mesh.faces(f, 2);
    // Lattice point (i, j), i + j <= parts: a + i (b - a)/parts + j (c - a)/parts.
    std::map<std::pair<int, int>, int> lattice;
    auto id = [&](int i, int j) {
      if (i == 0 && j == 0)
        return a;
      if (i == parts && j == 0)
        return b;
      if (i == 0 && j == parts)
        return c;
      if (j == 0)
        return edge_point(a, b, i);
      if (i == 0)
        return edge_point(a, c, j);
      if (i + j == parts)
        return edge_point(b, c, j);
      auto [it, inserted] = lattice.emplace(std::pair{i, j}, static_cast<int>(points.size()));
      if (inserted)
        points.push_back(points[a] + (points[b] - points[a]) * (double(i) / parts) +
                         (points[c] - points[a]) * (double(j) / parts));
      return it->second;
    };
    for (int j = 0; j < parts; ++j)
      for (int i = 0; i + j < parts; ++i)
      {
        triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        if (i + j + 1 < parts)
          triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  }
  geometry::SurfaceMesh fine;
  fine.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    fine.vertices.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  fine.faces.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t i = 0; i < triangles.size(); ++i)
    fine.faces.row(static_cast<Eigen::Index>(i)) << triangles[i][0], triangles[i][1], triangles[i][2];
  return fine;
}

FaceCones face_cones(const geometry::SurfaceMesh& mesh)
{
  const Eigen::Index n_faces = mesh.faces.rows();
  if (n_faces < 4 || mesh.vertices.rows() < 4)
    throw InputError("contact density: the mesh needs at least 4 vertices and 4 faces");
  FaceCones cones;
  cones.centre_m = geometry::mass_properties(mesh).centre_of_mass;
  cones.corners = mesh.vertices.rowwise() - cones.centre_m.transpose();
  cones.faces = mesh.faces;
  cones.neighbours.resize(n_faces, 3);
  cones.planes.resize(n_faces, 9);
  std::map<std::pair<int, int>, std::pair<int, int>> directed_edges; // (from, to) -> (face, k)
  for (Eigen::Index f = 0; f < n_faces; ++f)
    for (int k = 0; k < 3; ++k)
    {
      const int a = mesh.faces(f, k), b = mesh.faces(f, (k + 1) % 3);
      if (!directed_edges.emplace(std::pair{a, b}, std::pair{static_cast<int>(f), k}).second)
        throw InputError("contact density: the mesh is not consistently oriented (an edge is used twice in one "
                         "direction)");
      const Eigen::Vector3d pa = cones.corners.row(a), pb = cones.corners.row(b);
      cones.planes.row(f).segment<3>(3 * k) = pa.cross(pb).transpose();
    }
  for (Eigen::Index f = 0; f < n_faces; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = mesh.faces(f, k), b = mesh.faces(f, (k + 1) % 3);
      const auto twin = directed_edges.find({b, a});
      if (twin == directed_edges.end())
        throw InputError("contact density: the mesh is not closed (an edge has one face)");
      cones.neighbours(f, k) = twin->second.first;
    }
    const Eigen::Vector3d p0 = cones.corners.row(mesh.faces(f, 0)), p1 = cones.corners.row(mesh.faces(f, 1)),
                          p2 = cones.corners.row(mesh.faces(f, 2));
    if (!(p0.dot(p1.cross(p2)) > 0))
      throw InputError("contact density: the mesh's centre of mass is not strictly inside every face's cone (mesh "
                       "not convex or not outward)");
  }
  return cones;
}

int locate_face(const FaceCones& cones, const Eigen::Vector3d& point, int guess)
{
  const Eigen::Vector3d x = point - cones.centre_m;
  const int n_faces = static_cast<int>(cones.faces.rows());
  int f = (guess >= 0 && guess < n_faces) ? guess : 0;
  for (int step = 0; step < n_faces; ++step)
  {
    int worst = -1;
    double worst_value = 0;
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d normal = cones.planes.row(f).segment<3>(3 * k).transpose();
      const double value = normal.dot(x) / normal.norm();
      if (value < worst_value)
        worst = k, worst_value = value;
    }
    if (worst < 0)
      return f;
    f = cones.neighbours(f, worst);
  }
  // The walk cycled (possible only for degenerate cones): scan.
  for (int g = 0; g < n_faces; ++g)
  {
    bool inside = true;
    for (int k = 0; k < 3; ++k)
      inside = inside && cones.planes.row(g).segment<3>(3 * k).dot(x.transpose()) >= 0;
    if (inside)
      return g;
  }
  throw ComputationError("contact density: a point lies in no face's cone");
}

double contact_measure_rate(const RollingSample& sample, ContactMode mode, const ContactWidth& width, double s0,
                            double s1)
{
  const bool hertz = width.model == ContactWidthModel::hertz;
  const double e_star = width.effective_modulus_pa;
  if (mode == ContactMode::point)
  {
    if (!hertz)
      return 1.0;
    const double a = std::cbrt(3 * std::max(sample.normal_force_n, 0.0) * sample.start_radius_m / (4 * e_star));
    return std::numbers::pi * a * a;
  }
  const double length = (sample.contact_end_m - sample.contact_start_m).norm();
  if (!hertz)
    return length * (s1 - s0);
  // 2 b(s) L by two-point Gauss-Legendre on pieces of 1/64 of the ruling, so
  // that any union of slices of [0, 1] sums to the whole ruling's value.
  double sum = 0;
  const int pieces = std::max(1, static_cast<int>(std::lround(64 * (s1 - s0))));
  const double h = (s1 - s0) / pieces, offset = h / (2 * std::sqrt(3.0));
  for (int k = 0; k < pieces; ++k)
    for (const double s : {s0 + (k + 0.5) * h - offset, s0 + (k + 0.5) * h + offset})
    {
      const double load = line_load(sample.normal_force_n, sample.centre_of_pressure, length, s);
      const double radius = (1 - s) * sample.start_radius_m + s * sample.end_radius_m;
      sum += h / 2 * 2 * std::sqrt(std::max(4 * load * radius / (std::numbers::pi * e_star), 0.0)) * length;
    }
  return sum;
}

ContactDensity contact_density(const geometry::SurfaceMesh& mesh, const RollingTrajectory& trajectory,
                               const ContactWidth& width, double end_time_s)
{
  if (std::isnan(end_time_s))
    throw InputError("contact density: end time is NaN");
  const bool hertz = width.model == ContactWidthModel::hertz;
  if (hertz && !(std::isfinite(width.effective_modulus_pa) && width.effective_modulus_pa > 0))
    throw InputError(fmt::format("contact density: effective modulus (Pa) must be positive and finite, got {}",
                                 width.effective_modulus_pa));
  if (width.strip_slices < 1 || 64 % width.strip_slices != 0)
    throw InputError(fmt::format("contact density: strip slices must divide 64, got {}", width.strip_slices));
  const FaceCones cones = face_cones(mesh);
  ContactDensity density;
  density.width = width;
  density.face_areas_m2 = geometry::face_areas(mesh);
  density.measure = Eigen::VectorXd::Zero(mesh.faces.rows());
  Accumulator accumulator(cones, density.measure, density.fallback_scans);
  const int slices = (hertz && trajectory.mode == ContactMode::line) ? width.strip_slices : 1;

  auto rate = [&](const RollingSample& sample, double s0, double s1) {
    return contact_measure_rate(sample, trajectory.mode, width, s0, s1);
  };

  const auto& samples = trajectory.samples;
  const Eigen::Vector3d& o = cones.centre_m;
  for (std::size_t k = 0; k + 1 < samples.size() && samples[k].time_s < end_time_s; ++k)
  {
    const RollingSample& s0 = samples[k];
    const RollingSample& s1 = samples[k + 1];
    const double fraction = std::min(1.0, (end_time_s - s0.time_s) / (s1.time_s - s0.time_s));
    const double dt = fraction * (s1.time_s - s0.time_s);
    const Eigen::Vector3d a0 = s0.contact_start_m - o, b0 = s0.contact_end_m - o;
    const Eigen::Vector3d a1 = a0 + fraction * (s1.contact_start_m - o - a0);
    const Eigen::Vector3d b1 = b0 + fraction * (s1.contact_end_m - o - b0);
    for (int j = 0; j < slices; ++j)
    {
      const double lo = double(j) / slices, hi = double(j + 1) / slices;
      const double weight = 0.5 * (rate(s0, lo, hi) + rate(s1, lo, hi)) * dt;
      density.total_measure += weight;
      if (trajectory.mode == ContactMode::point)
      {
        accumulator.add({a0, a1, a1}, weight, true);
        continue;
      }
      const Eigen::Vector3d p0 = a0 + lo * (b0 - a0), q0 = a0 + hi * (b0 - a0);
      const Eigen::Vector3d p1 = a1 + lo * (b1 - a1), q1 = a1 + hi * (b1 - a1);
      accumulator.add({p0, p1, q1}, weight / 2, false);
      accumulator.add({p0, q1, q0}, weight / 2, false);
    }
  }
  return density;
}

Eigen::VectorXd density_per_area(const ContactDensity& density)
{
  return density.measure.cwiseQuotient(density.face_areas_m2);
}
} // namespace rollcheck::oracle

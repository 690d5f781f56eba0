// Discrete curvatures and the per-face Hertz quantities against the reference
// code's per-face outputs, and against analytic values on a sphere.
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "geometry/gaussian_curvature.h"
#include "geometry/internal_angles.h"
#include "geometry/mean_curvature.h"
#include "geometry/primitives.h"
#include "geometry/read_mesh.h"
#include "geometry/vertex_areas.h"
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <numbers>

namespace
{
using namespace rollcheck;
const std::string reference_dir = std::string(ROLLCHECK_REFERENCE_DATA_DIR);

class PerFace : public ::testing::TestWithParam<std::string>
{
};

TEST_P(PerFace, VertexCurvaturesAndEffectiveRadiiMatchReference)
{
  const std::string name = GetParam();
  const auto mesh = geometry::read_mesh(std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/" + name + "_reference.obj");
  const auto pf = nlohmann::json::parse(std::ifstream(reference_dir + "/perface_" + name + ".json"));
  const contact::FaceCurvature c = contact::face_curvature(mesh, {}, oracle::PaperCompat::reference());
  const auto h = pf["H_vertex"].get<std::vector<double>>();
  const auto k = pf["K_vertex"].get<std::vector<double>>();
  const auto r = pf["R_eff_face"].get<std::vector<double>>();
  ASSERT_EQ(h.size(), static_cast<std::size_t>(c.vertex_mean.size()));
  ASSERT_EQ(r.size(), static_cast<std::size_t>(c.effective_radius_m.size()));
  // The angles come from acos of a cosine; where a cosine differs by one ulp
  // (numpy's SIMD acos and sin differ from glibc's by an ulp) the oloid's
  // sharpest angle, 0.0019 rad, moves by up to 6e-11 relative (1 ulp /
  // sqrt(1 - cos^2) / theta). Curvatures are compared to 1e-10 relative;
  // values near zero (the cylinder's cap centres, H ~ 1e-16, K ~ 4e-14) are
  // rounding noise and compared on the body's scale, 1.
  auto close = [](double ours, double theirs, double scale) {
    return std::abs(ours - theirs) <= 1e-10 * std::max(std::abs(theirs), scale);
  };
  for (std::size_t v = 0; v < h.size(); ++v)
  {
    EXPECT_PRED3(close, c.vertex_mean[static_cast<Eigen::Index>(v)], h[v], 1.0) << "H at vertex " << v;
    EXPECT_PRED3(close, c.vertex_gaussian[static_cast<Eigen::Index>(v)], k[v], 1.0) << "K at vertex " << v;
  }
  for (std::size_t f = 0; f < r.size(); ++f)
    EXPECT_PRED3(close, c.effective_radius_m[static_cast<Eigen::Index>(f)], r[f], 1.0) << "R_eff at face " << f;
  const auto ref = nlohmann::json::parse(std::ifstream(reference_dir + "/reference_outputs.json"))["geometries"][name]["hertz"];
  EXPECT_NEAR(c.mean.mean(), ref["H_face_mean"].get<double>(), 1e-12);
  EXPECT_NEAR(c.gaussian.mean(), ref["K_face_mean"].get<double>(), 1e-12);
  EXPECT_EQ(c.flat_faces, ref["n_flat_faces"].get<long>());
}

INSTANTIATE_TEST_SUITE_P(Meshes, PerFace, ::testing::Values("oloid", "cylinder"));

TEST(DiscreteCurvature, AngleDefectsSumToFourPi)
{
  for (const auto& mesh : {geometry::icosphere(1.0, 3), geometry::cylinder(1.0, 2.0, 60),
                           geometry::read_mesh(std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/oloid_reference.obj")})
  {
    const auto angles = geometry::internal_angles(mesh);
    EXPECT_NEAR(geometry::angle_defects(mesh, angles).sum(), 4 * std::numbers::pi, 1e-10);
  }
}

TEST(DiscreteCurvature, MixedVoronoiAreasTileTheSurface)
{
  const auto mesh = geometry::read_mesh(std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/oloid_reference.obj");
  const auto angles = geometry::internal_angles(mesh);
  EXPECT_NEAR(geometry::mixed_voronoi_vertex_areas(mesh, angles).sum(), angles.areas.sum(), 1e-12);
  EXPECT_NEAR(geometry::barycentric_vertex_areas(mesh, angles).sum(), angles.areas.sum(), 1e-12);
}

TEST(DiscreteCurvature, SphereHasMeanCurvatureOneOverRAndGaussianOneOverRSquared)
{
  // Icosphere of radius 2 with 4 subdivisions: vertex curvatures converge to
  // H = 1/2, K = 1/4 with the mixed Voronoi areas (second order in the edge length).
  const double radius = 2.0;
  const auto mesh = geometry::icosphere(radius, 4);
  const auto angles = geometry::internal_angles(mesh);
  const Eigen::VectorXd areas = geometry::mixed_voronoi_vertex_areas(mesh, angles);
  const Eigen::VectorXd h = geometry::mean_curvature(mesh, angles, areas);
  const Eigen::VectorXd k = geometry::gaussian_curvature(mesh, angles, areas);
  EXPECT_NEAR(h.mean(), 1 / radius, 2e-3);
  EXPECT_NEAR(k.mean(), 1 / (radius * radius), 2e-3);
  EXPECT_LT((h.array() - 1 / radius).abs().maxCoeff(), 1e-2);
}

TEST(DiscreteCurvature, CylinderSideHasMeanCurvatureOneOverTwoR)
{
  // An open-ended prism of 5 rings x 60 sections closed by flat fans: the
  // middle ring sees only side faces, where H = 1 / (2 r) and K = 0.
  const int sections = 60;
  const double r = 1.5;
  geometry::SurfaceMesh tube;
  const int rings = 5;
  tube.vertices.resize(rings * sections + 2, 3);
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sections; ++j)
    {
      const double t = 2 * std::numbers::pi * j / sections;
      tube.vertices.row(i * sections + j) << r * std::cos(t), r * std::sin(t), 0.1 * i;
    }
  tube.vertices.row(rings * sections) << 0, 0, 0;
  tube.vertices.row(rings * sections + 1) << 0, 0, 0.1 * (rings - 1);
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i + 1 < rings; ++i)
    for (int j = 0; j < sections; ++j)
    {
      const int a = i * sections + j, b = i * sections + (j + 1) % sections;
      faces.push_back({a, b, b + sections});
      faces.push_back({a, b + sections, a + sections});
    }
  for (int j = 0; j < sections; ++j)
  {
    faces.push_back({rings * sections, (j + 1) % sections, j});
    faces.push_back({rings * sections + 1, (rings - 1) * sections + j, (rings - 1) * sections + (j + 1) % sections});
  }
  tube.faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    tube.faces.row(static_cast<Eigen::Index>(f)) << faces[f][0], faces[f][1], faces[f][2];
  const auto angles = geometry::internal_angles(tube);
  const Eigen::VectorXd areas = geometry::mixed_voronoi_vertex_areas(tube, angles);
  const Eigen::VectorXd h = geometry::mean_curvature(tube, angles, areas);
  const Eigen::VectorXd k = geometry::gaussian_curvature(tube, angles, areas);
  for (int j = 0; j < sections; ++j)
  {
    const int v = 2 * sections + j; // middle ring
    EXPECT_NEAR(h[v], 1 / (2 * r), 1e-3 / r);
    EXPECT_NEAR(k[v], 0.0, 1e-12);
  }
}

TEST(FacePressure, SphereOnPlaneMatchesHertzFormula)
{
  // One face of radius R = 0.01 m, F = 100 N, E* = E / (1 - nu^2):
  // a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2).
  contact::HertzParameters hertz;
  auto compat = oracle::PaperCompat::corrected();
  const Eigen::VectorXd radius = (Eigen::VectorXd(3) << 0.01, 2e5, std::numeric_limits<double>::infinity()).finished();
  const contact::FacePressure fp = contact::face_pressure(radius, hertz, compat);
  const double e_star = 200e9 / (1 - 0.09);
  const double a = std::cbrt(3 * 100.0 * 0.01 / (4 * e_star));
  EXPECT_NEAR(fp.contact_radius_m[0], a, 1e-15);
  EXPECT_NEAR(fp.peak_pressure_pa[0] / (3 * 100.0 / (2 * std::numbers::pi * a * a)), 1.0, 1e-14);
  EXPECT_EQ(fp.peak_pressure_pa[1], 0.0); // flatter than the flat-face radius
  EXPECT_EQ(fp.peak_pressure_pa[2], 0.0);
  compat.identical_bodies_modulus = true;
  const double ratio = contact::face_pressure(radius, hertz, compat).peak_pressure_pa[0] / fp.peak_pressure_pa[0];
  EXPECT_NEAR(ratio, std::pow(0.5, 2.0 / 3.0), 1e-14); // p0 ~ E*^(2/3)
}
} // namespace

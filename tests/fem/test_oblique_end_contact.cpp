// The rim end with its edge crossing the ruling obliquely
// (fem/mesh/rim_end_geometry.h RimEndGeometry::crossing_angle_rad,
// fem/scenes/rim_end_contact.h): the mesh covers both sides of the ruling up
// to the slanted edge (its sheet's area on each side against the trapezoid's),
// and a sharp obtuse edge grows as Williams's wedge at its dihedral angle
// normal to the edge, not at its section in the ruling's plane.
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "fem/mesh/oblique_end_angle.h"
#include "fem/mesh/rim_end_geometry.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/petsc_session.h"
#include "fem/scenes/rim_end_contact.h"
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <dolfinx/mesh/utils.h>
#include <gtest/gtest.h>
#include <mpi.h>
#include <numbers>
#include <span>

using namespace rollcheck;

namespace
{
constexpr double degree = std::numbers::pi / 180;
} // namespace

TEST(ObliqueEndContact, MeshCoversBothSidesUpToTheSlantedEdge)
{
  fem::ensure_petsc(); // MPI, before the mesh is distributed
  const double b = 2.4e-5, H = 10 * b, L = 3 * H, c = 30 * degree, section = 120 * degree;
  fem::RimEndSizes sizes;
  sizes.contact_m = b / 4;
  sizes.contact_zone_m = sizes.edge_zone_m = 1.5 * b;
  sizes.edge_m = b / 4;
  sizes.far_m = H / 4;
  sizes.crossing_angle_rad = c;
  const fem::RimEndGeometry geometry{0.01, section, 0.0, H, L, true, c};
  const fem::SceneMesh scene = fem::build_rim_end_mesh(MPI_COMM_WORLD, geometry, sizes);
  EXPECT_EQ(scene.symmetry_multiplicity, 1);
  EXPECT_TRUE(scene.symmetry_y_facets.empty());
  // The sheet z = 0 reaches from the far side x = -L to the edge x = y cot c:
  // on y > 0 the trapezoid H L + H^2 cot c / 2, on y < 0 H L - H^2 cot c / 2.
  std::span<const double> x = scene.mesh->geometry().x();
  const std::vector<std::int32_t> nodes
      = dolfinx::mesh::entities_to_geometry(*scene.mesh, 2, scene.contact_facets, false);
  double area[2] = {0, 0}, beyond_edge = 0;
  int on_centre_line = 0;
  for (std::size_t f = 0; f < scene.contact_facets.size(); ++f)
  {
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = Eigen::Vector3d(x[3 * nodes[3 * f + k]], x[3 * nodes[3 * f + k] + 1], x[3 * nodes[3 * f + k] + 2]);
    if (std::max({p[0].z(), p[1].z(), p[2].z()}) > 1e-9 * H)
      continue; // the other face
    const double y_mid = (p[0].y() + p[1].y() + p[2].y()) / 3;
    area[y_mid > 0 ? 0 : 1] += 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    for (const Eigen::Vector3d& q : p)
    {
      beyond_edge = std::max(beyond_edge, q.x() - fem::oblique_edge_x(section, c, q.y(), 0));
      on_centre_line += std::abs(q.y()) < 1e-9 * H;
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, area, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &beyond_edge, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &on_centre_line, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  const double slant = H * H / std::tan(c) / 2;
  EXPECT_NEAR(area[0] / (H * L + slant), 1.0, 1e-6);
  EXPECT_NEAR(area[1] / (H * L - slant), 1.0, 1e-6);
  EXPECT_LT(beyond_edge, 1e-9 * H);
  // The centre line y = 0 is a line of mesh nodes (the pressures along the ruling are read there).
  EXPECT_GT(on_centre_line, 20);
}

TEST(ObliqueEndContact, RoundedEdgeIsTheFilletOfTheSlantedEdge)
{
  // The slanted edge of the dihedral D filleted with r_e: in the section
  // normal to the edge (u = x sin c - y cos c beyond it, z up) the fillet is
  // the arc of radius r_e about (-x_t, r_e), x_t = r_e tan((180 deg - D) / 2),
  // from the sheet (u = -x_t) to the other face (u = -x_t + r_e sin D,
  // z = r_e (1 - cos(180 deg - D))), along the edge between y = -H and H.
  fem::ensure_petsc();
  const double b = 2.4e-5, H = 10 * b, L = 3 * H, c = 30 * degree, section = 120 * degree, r_e = 0.1 * H;
  const double D = fem::oblique_dihedral_angle(section, c), x_t = fem::fillet_start_distance(r_e, D);
  fem::RimEndSizes sizes;
  sizes.contact_m = b / 4;
  sizes.contact_zone_m = 1.5 * b;
  sizes.edge_zone_m = H; // the edge's elements along the whole fillet
  sizes.edge_m = r_e / 8;
  sizes.edge_x_m = -x_t;
  sizes.edge_band_m = r_e;
  sizes.far_m = H / 4;
  sizes.crossing_angle_rad = c;
  const fem::RimEndGeometry geometry{0.01, section, r_e, H, L, true, c};
  const fem::SceneMesh scene = fem::build_rim_end_mesh(MPI_COMM_WORLD, geometry, sizes);
  const Eigen::Vector3d n(std::sin(D) * std::sin(c), -std::sin(D) * std::cos(c), std::cos(D));
  const Eigen::Vector3d edge_normal(std::sin(c), -std::cos(c), 0); // u's direction
  std::span<const double> x = scene.mesh->geometry().x();
  const std::vector<std::int32_t> nodes
      = dolfinx::mesh::entities_to_geometry(*scene.mesh, 2, scene.contact_facets, false);
  // Areas: the sheet's on each side of the ruling, the fillet's projected
  // onto the sheet (exact for any facets whose nodes lie on the cylinder:
  // its boundary projects to straight lines), and the fillet's own.
  double area[4] = {0, 0, 0, 0}, off_cylinder = 0;
  for (std::size_t f = 0; f < scene.contact_facets.size(); ++f)
  {
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = Eigen::Vector3d(x[3 * nodes[3 * f + k]], x[3 * nodes[3 * f + k] + 1], x[3 * nodes[3 * f + k] + 2]);
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    const double z_max = std::max({p[0].z(), p[1].z(), p[2].z()});
    if (z_max < 1e-9 * H)
      area[(p[0].y() + p[1].y() + p[2].y()) > 0 ? 0 : 1] += 0.5 * normal.norm();
    else if (std::max({std::abs(n.dot(p[0])), std::abs(n.dot(p[1])), std::abs(n.dot(p[2]))}) < 1e-9 * H)
      continue; // the other face (obtuse: it faces the plane)
    else
    {
      area[2] += 0.5 * std::abs(normal.z());
      area[3] += 0.5 * normal.norm();
      for (const Eigen::Vector3d& q : p)
      {
        // Distance from the fillet's axis, the line u = -x_t, z = r_e along the edge.
        const double u = edge_normal.dot(q);
        off_cylinder = std::max(off_cylinder, std::abs(std::hypot(u + x_t, q.z() - r_e) - r_e));
      }
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, area, 4, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &off_cylinder, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  // The sheet ends where the fillet starts, x_t from the edge along its
  // normal: x_t / sin c back along the ruling, on both sides.
  const double slant = H * H / std::tan(c) / 2, cut_back = H * x_t / std::sin(c), along_edge = 2 * H / std::sin(c);
  EXPECT_NEAR(area[0] / (H * L + slant - cut_back), 1.0, 1e-6);
  EXPECT_NEAR(area[1] / (H * L - slant - cut_back), 1.0, 1e-6);
  EXPECT_NEAR(area[2] / (r_e * std::sin(D) * along_edge), 1.0, 1e-6);
  // Its own area, the arc r_e (180 deg - D) along the edge, less the
  // chords' shortfall: a chord of the angle t short of its arc by t^2 / 24,
  // t at most the angle of an element 1.5 times the size field's.
  const double fillet = r_e * (std::numbers::pi - D) * along_edge, t = 1.5 * sizes.edge_m / r_e;
  EXPECT_LT(area[3], fillet * (1 + 1e-9));
  EXPECT_GT(area[3], fillet * (1 - t * t / 24));
  EXPECT_LT(off_cylinder, 1e-6 * r_e);
}

TEST(ObliqueEndContact, BadObliqueSettingsAreNamed)
{
  fem::RimEndSettings s;
  s.crossing_angle_rad = 30 * degree;
  // A rounded oblique edge on the cylinder sheet (its fillet is no cylinder).
  s.edge_radius_m = 1e-6;
  s.sheet = fem::SheetModel::cylinder;
  EXPECT_THROW(fem::solve_rim_end(MPI_COMM_WORLD, s), InputError);
  s.sheet = fem::SheetModel::automatic;
  s.edge_radius_m = 0;
  s.length_over_depth = 2.5; // 1 + cot 30 deg = 2.73
  EXPECT_THROW(fem::solve_rim_end(MPI_COMM_WORLD, s), InputError);
  s.length_over_depth = 3;
  s.crossing_angle_rad = 100 * degree;
  EXPECT_THROW(fem::solve_rim_end(MPI_COMM_WORLD, s), InputError);
}

// Label long (tests/CMakeLists.txt, long_cases).
TEST(ObliqueEndContact, SharpEdgeGrowsAsTheWedgeAtItsDihedral)
{
  // Dihedral 120 deg normal to the edge, crossing the ruling at 30 deg: its
  // section in the ruling's plane is 139.1 deg, whose wedge is far more
  // singular. The perpendicular end at 120 deg measures within 10 % of the
  // wedge at 4 levels (RimEndContact.ObtuseSharpRimGrowsAsTheWedge).
  fem::RimEndSettings s;
  s.crossing_angle_rad = 30 * degree;
  const double dihedral = 120 * degree;
  s.interior_angle_rad = std::atan2(std::sin(dihedral), std::cos(dihedral) / std::sin(s.crossing_angle_rad));
  s.levels = 3;
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  EXPECT_NEAR(study.dihedral_angle_rad, dihedral, 1e-12);
  const double at_dihedral = contact::edge_on_rigid_plane_exponent(dihedral);
  const double at_section = contact::edge_on_rigid_plane_exponent(s.interior_angle_rad);
  EXPECT_DOUBLE_EQ(study.wedge_exponent, at_dihedral);
  ASSERT_TRUE(study.measured_exponent.has_value());
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("section %.2f deg: wedge %.4f at the dihedral, %.4f at the section, measured %.4f\n",
                s.interior_angle_rad / degree, at_dihedral, at_section, *study.measured_exponent);
  EXPECT_NEAR(*study.measured_exponent / at_dihedral, 1.0, 0.1);
  EXPECT_LT(std::abs(*study.measured_exponent - at_dihedral), std::abs(*study.measured_exponent - at_section));
  for (const fem::RimEndLevel& l : study.levels)
    EXPECT_NEAR(l.far_load_n_per_m / s.load_n_per_m, 1.0, 2e-3);
}

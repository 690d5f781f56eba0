// The rim end scene (fem/scenes/rim_end_contact.h) on the rigid plane: a square end
// is finite and converges, an obtuse sharp rim is singular with the growth
// exponent of Williams's mirrored wedge, a rounded obtuse rim converges.
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "fem/scenes/rim_end_contact.h"
#include "fem/petsc_session.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/steel_end_scene.h"
#include <algorithm>
#include <dolfinx/mesh/utils.h>
#include <cmath>
#include <cstdio>
#include <dolfinx/common/IndexMap.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>
#include <gtest/gtest.h>
#include <mpi.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double degree = std::numbers::pi / 180;

void print(const fem::RimEndStudy& study)
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0)
    return;
  for (const fem::RimEndLevel& l : study.levels)
    std::printf("h_e/b %.4f dofs %ld far/p0 %.4f (scatter %.3f) mid/far %.4f end/far %.4f at x/b %.3f edge/far "
                "%.4f wall %.1f\n",
                l.edge_element_m / study.half_width_m, static_cast<long>(l.dofs), l.far_peak_pa / study.hertz_peak_pa,
                l.far_scatter, l.mid_peak_pa / l.far_peak_pa, l.end_peak_pa / l.far_peak_pa,
                l.end_peak_x_m / study.half_width_m, l.edge_pressure_pa / l.far_peak_pa, l.wall_s);
  std::printf("wedge %.4f measured %.4f\n", study.wedge_exponent, study.measured_exponent.value_or(std::nan("")));
}
} // namespace

TEST(RimEndContact, SquareEndIsFiniteAndConverges)
{
  fem::RimEndSettings s;
  s.extra_levels = 1; // converged at the levels asked for: none added
  // The rim loop's progress names each level as it starts.
  std::vector<std::pair<int, double>> started;
  s.on_level = [&](int level, double edge_element_m) { started.emplace_back(level, edge_element_m); };
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(study);
  EXPECT_FALSE(study.singular);
  ASSERT_TRUE(study.end_change.has_value());
  EXPECT_TRUE(study.converged) << *study.end_change;
  EXPECT_EQ(study.levels.size(), static_cast<std::size_t>(s.levels));
  ASSERT_EQ(started.size(), study.levels.size());
  for (std::size_t k = 0; k < started.size(); ++k)
  {
    EXPECT_EQ(started[k].first, static_cast<int>(k));
    EXPECT_EQ(started[k].second, study.levels[k].edge_element_m);
  }
  EXPECT_FALSE(study.setup.on_level); // not kept: it refers to the caller's state
  // The far side is in plane strain: the middle's pressure is the far
  // side's within three standard errors of the nodes' scatter, which the
  // averages keep below 1 %.
  EXPECT_LT(study.plane_strain_noise, 0.01);
  EXPECT_LT(study.plane_strain_change, 3 * study.plane_strain_noise);
  // The free end lowers the pressure at the edge (0.51 of the far side's
  // measured) and refining does not make it grow, as a singular edge's would.
  ASSERT_TRUE(study.measured_exponent.has_value());
  EXPECT_GT(*study.measured_exponent, -0.05);
  EXPECT_LT(study.levels.back().edge_pressure_pa, study.levels.back().far_peak_pa);
  // Each level starts from the coarser level's approach, so the far side's
  // line load must read the same on every mesh: the weighted contact force
  // of its first depth H misses by 0.03-0.32 % there (one load step, two above
  // load control's 2e-3; measured here and on the 120 deg sharp rim and the
  // steel block's square end), where a trapezoid across one section missed
  // by 1.2-5.1 % (three load steps).
  for (std::size_t k = 0; k < study.levels.size(); ++k)
  {
    const fem::RimEndLevel& l = study.levels[k];
    EXPECT_NEAR(l.far_load_n_per_m / s.load_n_per_m, 1.0, 2e-3) << k;
    if (k > 0)
    {
      EXPECT_NEAR(l.start_load_n_per_m / s.load_n_per_m, 1.0, 0.01) << k;
      EXPECT_LE(l.load_steps, 2) << k;
    }
  }
}

// Label long (tests/CMakeLists.txt, long_cases).
TEST(RimEndContact, SquareEndAgreesOnAnIndependentGrid)
{
  // The same square end on a structured grid built without gmsh (h_e across
  // the edge, b / 12 along it): measured 0.5175 of the far side's pressure
  // at b / 128, 0.5234 at b / 64, against gmsh's 0.507 (converged to 0.5 %).
  fem::RimEndSettings s;
  const fem::RimEndStudy gmsh = fem::solve_rim_end(MPI_COMM_WORLD, s);
  s.mesh = fem::RimEndMesh::grid;
  s.contact_elements = 12;
  s.edge_element_over_half_width = 1.0 / 64;
  s.levels = 1;
  const fem::RimEndStudy grid = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(gmsh);
  print(grid);
  ASSERT_TRUE(gmsh.end_to_interior.has_value() && grid.end_to_interior.has_value());
  EXPECT_NEAR(*gmsh.end_to_interior / *grid.end_to_interior, 1.0, 0.04);
  // The grid's far side is line Hertz's p0 within its element scatter.
  EXPECT_NEAR(grid.levels.back().far_peak_pa / grid.hertz_peak_pa, 1.0, 0.02);
}

TEST(RimEndContact, StartingFromANeighboursApproachSavesLoadStepsNotAccuracy)
{
  // The rim loop's end table starts each node from the node before's
  // converged approach over line contact's estimate, which overshoots a held
  // block's approach by about 20 %: a neighbouring angle must reach the same
  // state in fewer load steps.
  fem::RimEndSettings s;
  s.levels = 1;
  const fem::RimEndStudy neighbour = fem::solve_rim_end(MPI_COMM_WORLD, s);
  EXPECT_GT(neighbour.approach_over_estimate(), 0.6);
  EXPECT_LT(neighbour.approach_over_estimate(), 0.95);
  s.interior_angle_rad = 85 * degree;
  const fem::RimEndStudy cold = fem::solve_rim_end(MPI_COMM_WORLD, s);
  s.first_approach_scale = neighbour.approach_over_estimate();
  const fem::RimEndStudy warm = fem::solve_rim_end(MPI_COMM_WORLD, s);
  const fem::RimEndLevel &c = cold.levels.front(), &w = warm.levels.front();
  std::printf("load steps %d cold, %d warm; Newton %d, %d\n", c.load_steps, w.load_steps, c.newton_iterations,
              w.newton_iterations);
  EXPECT_LT(w.load_steps, c.load_steps);
  EXPECT_LT(w.newton_iterations, c.newton_iterations);
  // Both carry q to load control's 2e-3; what they read agrees to about that.
  EXPECT_NEAR(w.approach_m / c.approach_m, 1.0, 4e-3);
  EXPECT_NEAR(w.far_peak_pa / c.far_peak_pa, 1.0, 4e-3);
  ASSERT_TRUE(cold.end_to_interior && warm.end_to_interior);
  EXPECT_NEAR(*warm.end_to_interior, *cold.end_to_interior, 4e-3);
  s.first_approach_scale = 0;
  EXPECT_THROW(fem::solve_rim_end(MPI_COMM_WORLD, s), InputError);
}

TEST(RimEndContact, SmallEndsAreFactorisedLargeOnesIteratedAndAGivenSolverWins)
{
  // One coarse level of the square end. MUMPS LU applies the factorisation
  // once a Newton step (one "Krylov iteration" each); GMRES + GAMG iterates.
  // All three solve the same problem: the same state to the solvers'
  // tolerance.
  fem::RimEndSettings s;
  s.levels = 1;
  s.contact_elements = 3;
  s.edge_element_over_half_width = 0.25;
  const fem::RimEndStudy direct = fem::solve_rim_end(MPI_COMM_WORLD, s);
  s.direct_solver_max_dofs = direct.levels.front().dofs - 1;
  const fem::RimEndStudy above = fem::solve_rim_end(MPI_COMM_WORLD, s);
  s.direct_solver_max_dofs = fem::RimEndSettings{}.direct_solver_max_dofs;
  s.petsc_options = "-hertz_ksp_type gmres -hertz_pc_type gamg";
  const fem::RimEndStudy given = fem::solve_rim_end(MPI_COMM_WORLD, s);
  const fem::RimEndLevel &d = direct.levels.front(), &a = above.levels.front(), &g = given.levels.front();
  std::printf("Newton / Krylov: direct %d / %d, above the bound %d / %d, given %d / %d\n", d.newton_iterations,
              d.krylov_iterations, a.newton_iterations, a.krylov_iterations, g.newton_iterations, g.krylov_iterations);
  EXPECT_EQ(d.krylov_iterations, d.newton_iterations);
  EXPECT_GT(a.krylov_iterations, 5 * a.newton_iterations);
  EXPECT_GT(g.krylov_iterations, 5 * g.newton_iterations);
  for (const fem::RimEndLevel* iterated : {&a, &g})
  {
    EXPECT_NEAR(iterated->end_peak_pa / d.end_peak_pa, 1.0, 1e-6);
    EXPECT_NEAR(iterated->far_peak_pa / d.far_peak_pa, 1.0, 1e-6);
  }
}

TEST(RimEndContact, EdgeElementsCoverTheRoundedEdgesBand)
{
  // The size field by hand: h_e over the band |x - x_t| <= w on the surface
  // within the edge zone, then growing with the distance from the band.
  fem::RimEndSizes sizes;
  sizes.edge_m = 1e-7;
  sizes.edge_x_m = -4e-4;
  sizes.edge_band_m = 2e-5;
  sizes.edge_zone_m = 5e-5;
  sizes.contact_m = 5e-6;
  sizes.contact_zone_m = 5e-5;
  sizes.far_m = 1e-3;
  for (const double dx : {-2e-5, -1e-5, 0.0, 1e-5, 2e-5})
  {
    const double on_band[3] = {sizes.edge_x_m + dx, 3e-5, 0.0};
    EXPECT_DOUBLE_EQ(fem::rim_end_element_size(sizes, on_band), sizes.edge_m) << dx;
  }
  const double beyond[3] = {sizes.edge_x_m + sizes.edge_band_m + 3e-6, 1e-5, 4e-6};
  EXPECT_NEAR(fem::rim_end_element_size(sizes, beyond), sizes.edge_m + sizes.growth * 5e-6, 1e-15);
  const double along[3] = {sizes.edge_x_m - sizes.edge_band_m - 3e-6, sizes.edge_zone_m + 4e-6, 0.0};
  EXPECT_NEAR(fem::rim_end_element_size(sizes, along), sizes.edge_m + sizes.growth * 5e-6, 1e-15);
  // No band: the line of the sharp edge alone.
  sizes.edge_band_m = 0;
  const double off_line[3] = {sizes.edge_x_m + 1e-5, 0.0, 0.0};
  EXPECT_NEAR(fem::rim_end_element_size(sizes, off_line), sizes.edge_m + sizes.growth * 1e-5, 1e-15);
}

TEST(RimEndContact, ConvergenceJudgesTheEndToInteriorRatio)
{
  // The 120 deg steel rim's levels b/128 and b/256 (test_rim_block_contact):
  // the end peak moved -3.05 % in Pa with the far side's -1.9 %; the ratio
  // 3.246 to 3.209, -1.17 %.
  fem::RimEndLevel coarse, fine;
  coarse.end_peak_pa = 4.8623e9;
  coarse.far_peak_pa = 1.498e9;
  fine.end_peak_pa = 4.7141e9;
  fine.far_peak_pa = 1.469e9;
  EXPECT_NEAR(fem::end_to_interior_change(coarse, fine, false), (4.7141 / 1.469 - 4.8623 / 1.498) / (4.7141 / 1.469),
              1e-12);
  EXPECT_NEAR(fem::end_to_interior_change(coarse, fine, false), -0.0117, 5e-4);
  // A sharp edge reports its own pressure; an acute one's falls towards
  // zero, measured against the interior's: 0.10 to 0.05 of it is -0.05.
  coarse.edge_pressure_pa = 0.10 * coarse.far_peak_pa;
  fine.edge_pressure_pa = 0.05 * fine.far_peak_pa;
  EXPECT_DOUBLE_EQ(fem::end_to_interior(fine, true), 0.05);
  EXPECT_NEAR(fem::end_to_interior_change(coarse, fine, true), -0.05, 1e-12);
}

TEST(RimEndContact, CentreLinePressureIsLinearBetweenItsNodes)
{
  // What the whole-body check matches an end model to a load rule with
  // (study/whole_body/whole_body_check.h): linear between the nodes either side, a node
  // itself exactly, nothing beyond the line.
  fem::RimEndLevel level;
  level.centre_line = {{-3.0, 10.0}, {-2.0, 20.0}, {-1.0, 40.0}, {0.0, 5.0}};
  EXPECT_DOUBLE_EQ(fem::centre_line_pressure_at(level, -2.0), 20.0);
  EXPECT_DOUBLE_EQ(fem::centre_line_pressure_at(level, -1.25), 35.0);
  EXPECT_DOUBLE_EQ(fem::centre_line_pressure_at(level, -3.0), 10.0);
  EXPECT_DOUBLE_EQ(fem::centre_line_pressure_at(level, 0.0), 5.0);
  EXPECT_THROW(fem::centre_line_pressure_at(level, -3.5), ComputationError);
  EXPECT_THROW(fem::centre_line_pressure_at(level, 0.5), ComputationError);
}

TEST(RimEndContact, OnlyFacesFacingThePlaneAreContactFacets)
{
  // A square or acute end's other face never touches the plane; had its
  // facets been contact facets, the edge nodes' recovered pressure would
  // average in their zero pressure (the square end read 0.27 instead of
  // 0.51). An obtuse end's other face faces the plane and may touch it.
  fem::ensure_petsc(); // MPI, before the mesh is distributed
  const double b = 2.4e-5, H = 10 * b;
  fem::RimEndSizes sizes;
  sizes.contact_m = b / 6;
  sizes.contact_zone_m = sizes.edge_zone_m = 1.5 * b;
  sizes.edge_m = b / 8;
  sizes.far_m = H / 4;
  for (const double angle_deg : {75.0, 90.0, 120.0})
  {
    const fem::RimEndGeometry geometry{0.01, angle_deg * degree, 0.0, H, 3 * H, true};
    const fem::SceneMesh scene = fem::build_rim_end_mesh(MPI_COMM_WORLD, geometry, sizes);
    const std::vector<double> mid
        = dolfinx::mesh::compute_midpoints(*scene.mesh, 2, scene.contact_facets);
    double highest = 0;
    for (std::size_t i = 0; i < scene.contact_facets.size(); ++i)
      highest = std::max(highest, mid[3 * i + 2]);
    double highest_anywhere = 0;
    MPI_Allreduce(&highest, &highest_anywhere, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (angle_deg > 90)
      EXPECT_GT(highest_anywhere, 0.5 * H) << angle_deg;
    else
      EXPECT_LT(highest_anywhere, 1e-9 * H) << angle_deg;
  }
}

TEST(RimEndContact, FilletNodesStandClearOfTheInterfaceTolerance)
{
  // The block's pairing takes nodes within fem::rim_interface_tolerance of
  // z = 0 for the interface. gmsh's fillet nodes nearest its start stand a
  // fraction of h_e^2 / (2 r_e) above it that the scale does not change, so
  // a coarse mesh tells how high they stand at the finest levels. The scene
  // of the preprint's body's 60 deg end on steel (b = 0.116 mm, H = 36.2 b,
  // r_e = 0.4 mm) at h_e = b / 8; its fourth level, h_e = b / 1406, stopped
  // on an unpaired interface node with the tolerance 1e-9 H.
  fem::ensure_petsc();
  const SteelEndScene end = mesh_preprint_steel_end();
  const double b = end.half_width_m, H = end.depth_m, edge_radius = end.edge_radius_m;
  const double fillet_start = end.fillet_start_m;
  const fem::RimEndSizes& sizes = end.sizes;
  const fem::SceneMesh& scene = end.scene;
  std::span<const double> x = scene.mesh->geometry().x();
  double lowest_on_fillet = 1e300, highest_on_interface = 0;
  for (std::size_t i = 0; i < x.size() / 3; ++i)
  {
    const double along = x[3 * i] + fillet_start, height = x[3 * i + 2];
    if (std::abs(height) < 1e-9 * H)
      highest_on_interface = std::max(highest_on_interface, std::abs(height));
    else if (along > 0.01 * sizes.edge_m && height > 0 && height < edge_radius)
      lowest_on_fillet = std::min(lowest_on_fillet, height);
  }
  MPI_Allreduce(MPI_IN_PLACE, &lowest_on_fillet, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &highest_on_interface, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  auto arc_height = [&](double h_e) { return h_e * h_e / (2 * edge_radius); };
  const double lowest_fraction = lowest_on_fillet / arc_height(sizes.edge_m);
  const double finest_edge = b / 1406, finest_lowest = lowest_fraction * arc_height(finest_edge);
  const double finest_tol = fem::rim_interface_tolerance(H, finest_edge, edge_radius);
  std::printf("lowest fillet node %.3g h_e^2 / (2 r_e); at h_e = b / 1406 %.3g m, tolerance %.3g m (1e-9 H %.3g m); "
              "highest interface node %.3g m\n",
              lowest_fraction, finest_lowest, finest_tol, 1e-9 * H, highest_on_interface);
  EXPECT_LT(finest_tol, 0.1 * finest_lowest);
  EXPECT_LT(highest_on_interface, 0.1 * finest_tol);
  // Edge elements so fine that the fillet's nodes come within the
  // coordinates' rounding of the interface: refused, not mispaired.
  EXPECT_THROW(fem::rim_interface_tolerance(1.0, 1e-9, 1e-3), ComputationError);
}

TEST(RimEndContact, ObtuseRoundedRimOnTheCylinderSheetIsBuilt)
{
  // At 170 deg the other face is nearly level, so on the cylinder sheet the
  // edge (the sheet cut by that face) leaves the block through its end x = H
  // before it crosses it in y (at y = 0.9 H for R = 10 mm, H = 10.5 r_e: the
  // preprint's body's end table at F = 800 N): its fillet must still be
  // found (it was not: "found 0 edge curves"). A coarse mesh is enough.
  fem::ensure_petsc();
  const double edge_radius = 4e-4, H = 10.5 * edge_radius;
  fem::RimEndSizes sizes;
  sizes.contact_m = sizes.edge_m = H / 20;
  sizes.contact_zone_m = sizes.edge_zone_m = H / 10;
  sizes.edge_x_m = -edge_radius * std::tan(5 * degree);
  sizes.far_m = H / 4;
  for (const double angle_deg : {120.0, 170.0})
  {
    const fem::RimEndGeometry geometry{0.01, angle_deg * degree, edge_radius, H, 3 * H, false};
    const fem::SceneMesh scene = fem::build_rim_end_mesh(MPI_COMM_WORLD, geometry, sizes);
    EXPECT_GT(scene.mesh->topology().index_map(3)->size_global(), 0) << angle_deg;
  }
}

TEST(RimEndContact, FlatSheetAgreesWithTheCylinder)
{
  // The reduction the scene uses where R >= 20 H (the preprint's load: R = 41 H),
  // against OpenCASCADE's cylinder: measured 0.947 / 0.954 (end peak) and
  // 0.523 / 0.533 (edge) of the far side's pressure at b / 16.
  fem::RimEndSettings s;
  s.levels = 2;
  s.sheet = fem::SheetModel::flat;
  const fem::RimEndStudy flat = fem::solve_rim_end(MPI_COMM_WORLD, s);
  s.sheet = fem::SheetModel::cylinder;
  const fem::RimEndStudy cylinder = fem::solve_rim_end(MPI_COMM_WORLD, s);
  EXPECT_TRUE(flat.flat_sheet);
  EXPECT_FALSE(cylinder.flat_sheet);
  const fem::RimEndLevel &f = flat.levels.back(), &c = cylinder.levels.back();
  EXPECT_NEAR(f.far_peak_pa / c.far_peak_pa, 1.0, 0.02);
  EXPECT_NEAR(f.end_peak_pa / f.far_peak_pa, c.end_peak_pa / c.far_peak_pa, 0.03);
  EXPECT_NEAR(f.edge_pressure_pa / f.far_peak_pa, c.edge_pressure_pa / c.far_peak_pa, 0.02);
}

TEST(RimEndContact, ObtuseSharpRimGrowsAsTheWedge)
{
  fem::RimEndSettings s;
  s.interior_angle_rad = 120 * degree;
  s.levels = 4;
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(study);
  EXPECT_TRUE(study.singular);
  ASSERT_TRUE(study.measured_exponent.has_value());
  EXPECT_NEAR(*study.measured_exponent / study.wedge_exponent, 1.0, 0.1);
}

TEST(RimEndContact, RoundedRimIsResolvedOnlyBelowItsBoundaryLayer)
{
  // At the preprint's load (p0 = 0.26 GPa) a fillet of b / 2 has a boundary
  // layer s = 0.0006 b: edge elements of b / 16 and b / 32 do not resolve it,
  // and the study must say so rather than call the peak converged.
  fem::RimEndSettings s;
  s.interior_angle_rad = 120 * degree;
  s.edge_radius_m = 1.2e-5;
  s.edge_element_over_half_width = 1.0 / 16;
  s.levels = 2;
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(study);
  EXPECT_FALSE(study.singular);
  EXPECT_LT(study.boundary_layer_m, 1e-3 * study.half_width_m);
  EXPECT_FALSE(study.resolved);
  EXPECT_FALSE(study.converged);
}

TEST(RimEndContact, RoundedObtuseRimConvergesOnceResolved)
{
  // A bearing's load, p0 = 2.0 GPa (q = pi R p0^2 / E*), and a fillet of 2 b:
  // s = 0.023 b, resolved at the third level (b / 256 <= s / 4). Two levels
  // are asked for and up to two more allowed: the study adds the third,
  // since b / 128 does not resolve s, and stops there, converged. Meshed by
  // gmsh's HXT (--end-mesh hxt: 25 s on 2 ranks against Delaunay's 37 s,
  // 3.39-3.44 from run to run against 3.3630, its far side nearer line
  // Hertz's p0: docs/methods/rims.md); Delaunay's rounded ends are the tests
  // above.
  fem::RimEndSettings s;
  s.mesh = fem::RimEndMesh::hxt;
  s.interior_angle_rad = 120 * degree;
  s.load_n_per_m = 571769.86;
  const double b = 1.82e-4;
  s.edge_radius_m = 2 * b;
  s.depth_over_half_width = 25;
  s.edge_element_over_half_width = 1.0 / 64;
  s.levels = 2;
  s.extra_levels = 2;
  // The fields are written once, at the end: the last level's nodes.
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "rollcheck_rim_fields";
  std::filesystem::create_directories(folder);
  s.xdmf_path = folder / "rounded.xdmf";
  std::filesystem::remove(s.xdmf_path);
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(study);
  EXPECT_NEAR(study.half_width_m / b, 1.0, 0.01);
  EXPECT_FALSE(study.singular);
  EXPECT_EQ(study.levels.size(), 3U);
  std::ifstream xdmf(s.xdmf_path);
  const std::string text((std::istreambuf_iterator<char>(xdmf)), std::istreambuf_iterator<char>());
  const std::size_t geometry = text.find("<Geometry");
  ASSERT_NE(geometry, std::string::npos) << s.xdmf_path;
  const std::size_t dimensions = text.find("Dimensions=\"", geometry) + std::string("Dimensions=\"").size();
  EXPECT_EQ(std::stoll(text.substr(dimensions)), study.levels.back().dofs / 3) << "nodes in " << s.xdmf_path;
  std::filesystem::remove(s.xdmf_path);
  std::filesystem::remove(std::filesystem::path(s.xdmf_path).replace_extension(".h5")); // the fields' data
  EXPECT_GT(study.levels[1].edge_element_m, study.boundary_layer_m / 4);
  EXPECT_TRUE(study.resolved);
  EXPECT_TRUE(study.converged) << study.end_change.value_or(std::nan(""));
  // The pressure peaks where the contact runs onto the fillet, just past
  // x_t = r_e tan 30 deg, above the interior's.
  EXPECT_NEAR(study.levels.back().end_peak_x_m / study.fillet_start_m, -1.0, 0.1);
  ASSERT_TRUE(study.end_to_interior.has_value());
  EXPECT_GT(*study.end_to_interior, 1.5);
}

TEST(RimEndContact, RoundedAcuteRimPeaksWhereItsFilletStarts)
{
  // Below 90 deg the fillet leaves the sheet further out than r_e
  // (x_t = r_e tan 60 deg = 8.7 b at 60 deg, r_e = 5 b): the sheet's end,
  // where the curvature jumps, carries the peak, and the study must look for
  // it there (it once looked within 2 b + r_e = 7 b, found no pressure and
  // stopped the loop at the oloid's acute ends). Meshed by gmsh's HXT, as
  // the obtuse rim above.
  fem::RimEndSettings s;
  s.mesh = fem::RimEndMesh::hxt;
  s.interior_angle_rad = 60 * degree;
  s.load_n_per_m = 571769.86; // p0 = 2.0 GPa at R = 10 mm: b = 0.182 mm
  const double b = 1.82e-4;
  s.edge_radius_m = 5 * b;
  s.depth_over_half_width = 52;
  s.edge_element_over_half_width = 1.0 / 64;
  s.levels = 2;
  // HXT's meshes differ from run to run (about a hundred DOFs in 87,000), and
  // the end's change from b/64 to b/128 with them: -2.3 to -3.4 % against the
  // 3 % tolerance (-1.3 % to b/256). The study adds a level where it needs
  // one, as a user's run would.
  s.extra_levels = 1;
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(study);
  EXPECT_GT(study.fillet_start_m, 2 * b + s.edge_radius_m);
  EXPECT_TRUE(study.resolved);
  EXPECT_TRUE(study.converged) << study.end_change.value_or(std::nan(""));
  EXPECT_NEAR(study.levels.back().end_peak_x_m / study.fillet_start_m, -1.0, 0.1);
  ASSERT_TRUE(study.end_to_interior.has_value());
  EXPECT_GT(*study.end_to_interior, 1.2);
}

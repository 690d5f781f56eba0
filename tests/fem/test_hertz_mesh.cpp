// The 3D Hertz scene mesh's contact refinement (fem/mesh/hertz_mesh.h): the
// contact surface's triangles are about the pole's and the edge's sizes in
// the ball about the first point of contact and in the tube about the edge
// circle, and about the grading's h_c between them and without refinement.
// Edge lengths of gmsh's Frontal-Delaunay triangles scatter about the size
// field's value by some 20 %: the bounds compare means with a factor-2
// refinement, far apart from each other.
#include "fem/mesh/hertz_mesh.h"
#include "fem/petsc_session.h"
#include <cmath>
#include <gtest/gtest.h>

// DOLFINx says `using namespace dolfinx` at global scope: its fem would clash with ours.
namespace rf = rollcheck::fem;

namespace
{
constexpr double radius = 0.01, contact = 1.5e-4, h_c = contact / 10;

/// Mean length of the contact triangles' edges whose midpoints lie in a
/// region, on this rank.
struct RegionEdges
{
  double pole = 0, middle = 0, edge = 0; ///< s < 0.2 c; 0.4 c < s < 0.7 c; |s - c| < 0.05 c (on the surface)
};

RegionEdges mean_edge_lengths(const rf::SceneMesh& scene)
{
  const dolfinx::mesh::Mesh& mesh = *scene.mesh;
  const std::vector<std::int32_t> nodes = dolfinx::mesh::entities_to_geometry(mesh, 2, scene.contact_facets, false);
  std::span<const double> x = mesh.geometry().x();
  double sum[3] = {0, 0, 0};
  int count[3] = {0, 0, 0};
  for (std::size_t f = 0; f < nodes.size(); f += 3)
    for (int i = 0; i < 3; ++i)
    {
      const double* p = &x[3 * nodes[f + i]];
      const double* q = &x[3 * nodes[f + (i + 1) % 3]];
      const double s = std::hypot(0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])) / contact;
      const int region = s < 0.2 ? 0 : (s > 0.4 && s < 0.7) ? 1 : std::abs(s - 1) < 0.05 ? 2 : -1;
      if (region < 0)
        continue;
      sum[region] += std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
      ++count[region];
    }
  EXPECT_GT(count[0], 0);
  EXPECT_GT(count[1], 0);
  EXPECT_GT(count[2], 0);
  return {sum[0] / count[0], sum[1] / count[1], sum[2] / count[2]};
}
} // namespace

TEST(HertzMesh, ContactRefinementHalvesTheSurfaceElementsAtThePoleAndTheEdge)
{
  rf::ensure_petsc();
  const rf::MeshGrading grading = rf::contact_grading(contact, h_c, radius);
  const RegionEdges plain = mean_edge_lengths(rf::build_scene_mesh(MPI_COMM_SELF, rf::Model::solid, radius, grading));
  const rf::ContactRefinement refinement{.pole_size_m = h_c / 2,
                                         .pole_radius_m = 0.25 * contact,
                                         .edge_size_m = h_c / 2,
                                         .edge_half_width_m = 0.1 * contact,
                                         .edge_radius_m = contact};
  const RegionEdges refined
      = mean_edge_lengths(rf::build_scene_mesh(MPI_COMM_SELF, rf::Model::solid, radius, grading, refinement));
  for (double mean : {plain.pole, plain.middle, plain.edge, refined.middle})
  {
    EXPECT_GT(mean, 0.8 * h_c);
    EXPECT_LT(mean, 1.25 * h_c);
  }
  for (double mean : {refined.pole, refined.edge})
  {
    EXPECT_GT(mean, 0.4 * h_c);
    EXPECT_LT(mean, 0.625 * h_c);
  }
}

// The structured contact cap (ContactRefinement::cap): every node of the
// contact surface within the cap lies on a designed ring to 1e-9 of the cap's
// radius, ring j holds its designed nodes (none between rings), and no node
// lies within the designed clearance, half the rings' spacing, of the
// Hertz edge.
TEST(HertzMesh, StructuredCapPutsTheSurfaceNodesOnRingsClearOfTheEdge)
{
  rf::ensure_petsc();
  const rf::MeshGrading grading = rf::contact_grading(contact, h_c, radius);
  const double h_e = h_c / 2; // rings h <= h_e apart inside the contact
  rf::ContactRefinement refinement;
  refinement.cap = rf::cap_rings({.edge_radius_m = contact,
                                  .spacing_m = h_e,
                                  .far_spacing_m = h_c,
                                  .edge_segment_m = h_c,
                                  .cap_radius_m = 2 * contact,
                                  .growth = grading.growth});
  const std::vector<double>& rings = refinement.cap.radius_m;
  const rf::SceneMesh scene = rf::build_scene_mesh(MPI_COMM_SELF, rf::Model::solid, radius, grading, refinement);
  const dolfinx::mesh::Mesh& mesh = *scene.mesh;
  const std::vector<std::int32_t> facet_nodes
      = dolfinx::mesh::entities_to_geometry(mesh, 2, scene.contact_facets, false);
  std::vector<std::int32_t> nodes(facet_nodes.begin(), facet_nodes.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::span<const double> x = mesh.geometry().x();
  const double s_cap = rings.back(), tol = 1e-9 * s_cap;
  std::vector<int> on_ring(rings.size(), 0);
  for (std::int32_t node : nodes)
  {
    const double s = std::hypot(x[3 * node], x[3 * node + 1]);
    if (s > s_cap + tol)
      continue;
    const auto nearest = std::min_element(rings.begin(), rings.end(),
                                          [s](double p, double q) { return std::abs(p - s) < std::abs(q - s); });
    ASSERT_LT(std::abs(*nearest - s), tol) << "node at s = " << s / contact << " c";
    ++on_ring[nearest - rings.begin()];
    EXPECT_GT(std::abs(s - contact), rings[1] / 2 - tol);
  }
  for (std::size_t j = 0; j < rings.size(); ++j)
    EXPECT_EQ(on_ring[j], refinement.cap.angles_rad[j].size()) << "ring " << j << " at " << rings[j] / contact << " c";
}

#pragma once
// The scenes the block pairing's tests mesh: a rounded rim end on steel as
// the rim block scene (fem/mesh/scene_mesh.h build_rim_block_mesh) at coarse edge
// elements, h_e = b / 8, which gmsh meshes in seconds. The preprint's body's
// 60 deg end (b = 0.116 mm, H = 36.2 b, r_e = 0.4 mm, R = 22.4 mm; the end
// table's node whose fillet swung, docs/notes/rim-runs.md) and the oloid's
// square end at its loop's load (b = 34.6 um, r_e = 11.5 b; its pairing met
// a side plane's facet on the fillet's arc, docs/methods/rims.md).
#include "fem/mesh/scene_mesh.h"
#include <mpi.h>
#include <numbers>

struct SteelEndScene
{
  double half_width_m = 1.16e-4;
  double depth_m = 36.2 * 1.16e-4;
  double edge_radius_m = 4e-4;
  double interior_angle_rad = 60 * std::numbers::pi / 180;
  double sheet_radius_m = 0.0224;
  double fillet_start_m = rollcheck::fem::fillet_start_distance(edge_radius_m, interior_angle_rad);
  rollcheck::fem::RimEndSizes sizes;
  rollcheck::fem::SceneMesh scene;
};

inline SteelEndScene mesh_steel_end(SteelEndScene end)
{
  const double b = end.half_width_m, H = end.depth_m;
  end.fillet_start_m = rollcheck::fem::fillet_start_distance(end.edge_radius_m, end.interior_angle_rad);
  end.sizes.contact_m = b / 6;
  end.sizes.contact_zone_m = end.sizes.edge_zone_m = 1.5 * b;
  end.sizes.edge_m = b / 8;
  end.sizes.edge_x_m = -end.fillet_start_m;
  end.sizes.edge_band_m = 0.5 * b;
  end.sizes.far_m = H / 4;
  const rollcheck::fem::RimEndGeometry geometry{end.sheet_radius_m, end.interior_angle_rad, end.edge_radius_m, H,
                                                3 * H, true};
  end.scene = rollcheck::fem::build_rim_block_mesh(MPI_COMM_WORLD, geometry, end.sizes);
  return end;
}

inline SteelEndScene mesh_preprint_steel_end() { return mesh_steel_end({}); }

/// The oloid's square end (90.04 deg) in its steel loop, at `depth_over_b`.
inline SteelEndScene mesh_oloid_square_steel_end(double depth_over_b)
{
  SteelEndScene end;
  end.half_width_m = 3.464e-5;
  end.depth_m = depth_over_b * end.half_width_m;
  end.interior_angle_rad = 90.0396 * std::numbers::pi / 180;
  end.sheet_radius_m = 9.3728e-4;
  return mesh_steel_end(end);
}

#pragma once
// The scene the block pairing's tests mesh: the preprint's body's 60 deg end
// on steel (b = 0.116 mm, H = 36.2 b, r_e = 0.4 mm, R = 22.4 mm; the end
// table's node whose fillet swung, docs/rim-results.md) as the rim block
// scene (fem/scene_mesh.h build_rim_block_mesh) at coarse edge elements,
// h_e = b / 8: gmsh meshes it in a few seconds.
#include "fem/scene_mesh.h"
#include <mpi.h>
#include <numbers>

struct PreprintSteelEnd
{
  double half_width_m = 1.16e-4;
  double depth_m = 36.2 * 1.16e-4;
  double edge_radius_m = 4e-4;
  double interior_angle_rad = 60 * std::numbers::pi / 180;
  double fillet_start_m = rollcheck::fem::fillet_start_distance(edge_radius_m, interior_angle_rad);
  rollcheck::fem::RimEndSizes sizes;
  rollcheck::fem::SceneMesh scene;
};

inline PreprintSteelEnd mesh_preprint_steel_end()
{
  PreprintSteelEnd end;
  const double b = end.half_width_m, H = end.depth_m;
  end.sizes.contact_m = b / 6;
  end.sizes.contact_zone_m = end.sizes.edge_zone_m = 1.5 * b;
  end.sizes.edge_m = b / 8;
  end.sizes.edge_x_m = -end.fillet_start_m;
  end.sizes.edge_band_m = 0.5 * b;
  end.sizes.far_m = H / 4;
  const rollcheck::fem::RimEndGeometry geometry{0.0224, end.interior_angle_rad, end.edge_radius_m, H, 3 * H, true};
  end.scene = rollcheck::fem::build_rim_block_mesh(MPI_COMM_WORLD, geometry, end.sizes);
  return end;
}

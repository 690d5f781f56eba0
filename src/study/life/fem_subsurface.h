#pragma once
// Wing of the study layer (study/life): the FEM slice's subsurface stress
// against the closed form of line contact, under mesh refinement.
//
// One plane-strain slice of a loaded ruling (fem/scenes/slice_contact.h
// solve_slice_subsurface) is solved at several contact-zone refinements;
// at each, its largest principal shear on the axis, the depth of it, and
// its orthogonal shear at the extremum near (0.87 b, 0.5 b), each over the
// Hertz p0 and b of the load it carries, are set against the closed form
// (contact/subsurface_pass.h: 0.300 p0 at 0.786 b; 0.250 p0 at 0.5 b,
// 0.87 b). The finest level's ratios FEM / closed form are the corrections
// the life integrals apply to the closed-form field (loop_life.h).
#include "fem/scenes/slice_contact.h"
#include <nlohmann/json.hpp>
#include <vector>

namespace rollcheck::study::life
{
struct SubsurfaceSettings
{
  double radius_m = 1;              ///< the slice's R: the cylinder's (radius 1 m)
  double load_n_per_m = 2500;       ///< its q: the cylinder's at 5000 N (length 2 m)
  std::vector<int> refines = {2, 4, 6};
  /// P2: P1's recovered shear stays biased under refinement (docs/methods/life.md)
  int degree = 2;
  fem::SliceSettings slice = [] {
    fem::SliceSettings s;
    s.elastic_plane = true; // steel on steel, the loop's E*
    return s;
  }();
};

struct SubsurfaceLevel
{
  fem::SliceSubsurface fem;
  double max_shear_over_p0 = 0, max_shear_depth_over_b = 0;
  double orthogonal_shear_over_p0 = 0, orthogonal_shear_depth_over_b = 0, orthogonal_shear_offset_over_b = 0;
};

struct SubsurfaceCheck
{
  SubsurfaceSettings settings;
  std::vector<SubsurfaceLevel> levels;          ///< coarse to fine
  double closed_max_shear_over_p0 = 0, closed_max_shear_depth_over_b = 0;
  double closed_orthogonal_shear_over_p0 = 0, closed_orthogonal_shear_depth_over_b = 0,
         closed_orthogonal_shear_offset_over_b = 0;
  /// Finest level over the closed form: the life integrals' corrections.
  double max_shear_ratio = 1, orthogonal_shear_ratio = 1;
  double wall_s = 0;
};

/// Every level on this process (2D solves of seconds each).
SubsurfaceCheck check_subsurface(const SubsurfaceSettings& settings, double poisson_ratio);

nlohmann::json to_json(const SubsurfaceCheck& check);
} // namespace rollcheck::study::life

#pragma once
// The sections' share of the load (`whole-body --share-rule sections`): how a body standing on its contact ruling shares
// its load F along the ruling when each section across the ruling carries
// what its own compliance gives (fem/scenes/section_contact.h), not what the
// contact locus's no-tension linear rule of a rigid footing assigns
// (contact/contact_locus.h).
//
// Compatibility: the body's cut z = z_G through its centre of mass moves
// rigidly, down by delta(x) = delta_0 + t (x - x_G) along the ruling (an
// approach and a tilt, the whole body's loading, fem/scenes/whole_body_contact.h);
// a section at station x carries q_x(delta(x)), its plane-strain line load
// at that approach. Equilibrium picks delta_0 and t:
//   int_0^L q dx = F,   int_0^L q (x - x_G) dx = 0,
// the integrals by the midpoint rule over N stations x_k = (k + 1/2) L / N.
// This is the slicing technique of roller-bearing analysis (T. A. Harris,
// M. N. Kotzalas, "Rolling Bearing Analysis", 5th ed., 2007, ch. 6: the
// roller cut into laminae, each with its own load-deflection relation, under
// one rigid approach and tilt) with the laminae's relation computed from the
// body's own sections instead of a half-space formula. Neighbouring sections
// do not share load through shear here (plane strain each): the whole body's
// check (study/whole_body/whole_body_check.h) measures what that leaves out.
//
// Iteration: each section's load follows q = Q (delta / D)^n through its
// last two solves (n = 1.1, line contact's, before the second); the 2 x 2
// equilibrium is solved by Newton on that model, every section solved at
// its new approach, until the solved loads meet the model's within
// `tolerance`.
#include "fem/scenes/section_contact.h"
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <vector>

namespace rollcheck::study::whole_body
{
struct SectionShareSettings
{
  int stations = 16;       ///< N
  double tolerance = 1e-3; ///< largest |q solved / q predicted - 1| of the last pass
  int max_passes = 10;
};

struct SectionShare
{
  std::vector<double> stations_m, load_n_per_m, approach_m, peak_pressure_pa;
  double approach_at_centre_of_mass_m = 0; ///< delta_0
  double tilt_rad = 0;                     ///< t
  double force_n = 0;                      ///< the midpoint rule's int q dx of the last solves
  double centre_of_pressure_m = 0;         ///< its int q x dx / F
  int passes = 0;
  double last_change = 0;                  ///< largest |q solved / q predicted - 1| of the last pass
  std::int64_t section_dofs = 0;           ///< of the first section
  double wall_s = 0;
  /// q(x): linear between the stations, extended linearly beyond the outer
  /// ones to the ruling's ends.
  double load_at(double x_m) const;
};

/// Every rank gets the result. InputError for bad settings; ComputationError
/// when a section fails or the iteration does not meet `tolerance` in
/// max_passes.
SectionShare section_share(MPI_Comm comm, const fem::MappedBodyPose& pose, double force_n,
                                  double centre_of_mass_along_m, double first_approach_m,
                                  const fem::WholeBodySizes& sizes, const fem::SectionSettings& section,
                                  const SectionShareSettings& settings);

nlohmann::json to_json(const SectionShare& rule);
} // namespace rollcheck::study::whole_body

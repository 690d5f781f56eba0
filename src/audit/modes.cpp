#include "audit/modes.h"

namespace rollcheck::audit
{
std::vector<std::pair<std::string, std::string>> audit_modes()
{
  return {
      {mode::paper, "the reference code's arithmetic and quirks (`--paper-compat`), rigid-body oracle, on the meshes "
                    "it scored (meshes/reference: oloid 1198 faces, cylinder 240)"},
      {mode::matched, "paper-compatible, but the cylinder meshed with 300 sides (1200 faces, the oloid's 1198) instead "
                      "of 60; in the search the anchor oloid meshed like the candidates (`--matched-resolution`)"},
      {mode::true_oloid, "paper-compatible, with the true oloid (`--body oloid`: hull of two unit circles in "
                         "perpendicular planes, each through the other's centre) instead of the preprint's (90,1,1) "
                         "roller"},
      {mode::corrected, "every paper-compat quirk switch corrected (no `--paper-compat`; docs/results/oracles.md#paper-compat-quirk-table); for the "
                        "FEM item, the penalty-contact FEM against analytic Hertz"},
      {mode::rolling, "rolling without slipping under gravity from the stable ruling with 1.1x the barrier energy, "
                      "exact support sets, Hertz contact width, scored with U_inf, the normalised uniformity score "
                      "on the exact surface (`uniformity_score_continuum` of `rollcheck oracle --oracle rolling`; the "
                      "coverage on the mesh with faces cut 8 x 8); U is a different score than CDS, so this column "
                      "compares discrimination (which body is more uniform), not values"},
      {mode::contact, "one loop of real rolling (16384 samples), every sample's contact ruling loaded by F through the "
                      "centre of mass and scored with the plane-strain penalty FEM through its exact scaling "
                      "(`rollcheck fem-sds`, issue 13), each score converged (FEM table K to 2K and samples halved, "
                      "both under 1 %); the preprint's body (1198 faces) against the cylinder with 300 sides (1200 "
                      "faces); pressures are taken 5 % of the ruling inside its ends (the rims are issue 14)"},
      {mode::life, "rolling-contact fatigue life from the subsurface shear over one loop (`rollcheck life`, issue 60): "
                   "L10 life ratios by Lundberg-Palmgren's and Ioannides-Harris's stress-volume integrals at 100 N, "
                   "5000 N and the load of a 1.5 GPa peak on the cylinder, over the grid of modelling choices; the "
                   "rounded rim ends at the grid's default cell"},
  };
}
} // namespace rollcheck::audit

// The body's sections in plane strain at prescribed approaches
// (fem/scenes/section_contact.h).
#include "fem/scenes/section_contact.h"
#include "core/error.h"
#include "fem/nodal_fields.h"
#include "fem/penalty_contact.h"
#include "fem/petsc_session.h"
#include "fem/share_out.h"
#include <algorithm>
#include <chrono>
#include <fmt/format.h>

namespace rollcheck::fem
{
namespace
{
constexpr std::size_t packed_size = 5;

SectionFem solve_section(const MappedBodyPose& pose, double station_m, double approach_m, const WholeBodySizes& sizes,
                         const SectionSettings& settings)
{
  const auto start = std::chrono::steady_clock::now();
  const double thickness = sizes.contact_m;
  const WholeBodyMesh mesh = build_mapped_section_mesh(MPI_COMM_SELF, pose, station_m, thickness, sizes);
  const double kappa = settings.penalty_c * settings.youngs_modulus_pa / sizes.contact_m;
  PenaltyContact problem(mesh.scene, Model::solid, 1, settings.youngs_modulus_pa, settings.poisson_ratio, kappa,
                         settings.petsc_options);
  problem.set_initial_gap(mesh.initial_gap);
  problem.start_translated(settings.first_shift_m, approach_m);
  const NewtonReport newton = problem.solve();
  SectionFem r;
  r.station_m = station_m;
  r.approach_m = approach_m;
  r.load_n_per_m = problem.reaction_force_n() / thickness;
  for (const SurfacePressureNode& node : gather_surface_pressure(MPI_COMM_SELF, recover_contact_pressure(problem)))
    r.peak_pressure_pa = std::max(r.peak_pressure_pa, node.pressure_pa);
  r.dofs = problem.num_dofs();
  r.newton_iterations = newton.newton_iterations;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}
} // namespace

std::vector<SectionFem> solve_sections(MPI_Comm comm, const MappedBodyPose& pose, std::span<const double> stations_m,
                                       std::span<const double> approaches_m, const WholeBodySizes& sizes,
                                       const SectionSettings& settings)
{
  if (stations_m.size() != approaches_m.size())
    throw InputError(fmt::format("sections: {} stations but {} approaches", stations_m.size(), approaches_m.size()));
  for (const double station : stations_m)
    if (!(station >= 0 && station <= pose.length_m))
      throw InputError(fmt::format("sections: a station at {} m lies off the ruling [0, {}] m", station,
                                   pose.length_m));
  for (const double delta : approaches_m)
    if (!(delta > 0))
      throw InputError(fmt::format("sections: an approach of {} m; approaches must be positive", delta));
  if (!(settings.first_shift_m >= 0) || !(settings.penalty_c > 0))
    throw InputError(fmt::format("sections: first shift {} m must be >= 0 and penalty c {} positive",
                                 settings.first_shift_m, settings.penalty_c));
  ensure_petsc();
  const std::vector<double> packed = share_out(
      comm, stations_m.size(), packed_size,
      [&](std::size_t i) {
        const SectionFem r = solve_section(pose, stations_m[i], approaches_m[i], sizes, settings);
        return std::vector<double>{r.load_n_per_m, r.peak_pressure_pa, static_cast<double>(r.dofs),
                                   static_cast<double>(r.newton_iterations), r.wall_s};
      },
      [&](std::size_t i) {
        return fmt::format("section at {:.6g} m (approach {:.6g} m)", stations_m[i], approaches_m[i]);
      },
      "plane-strain section solve");
  std::vector<SectionFem> results(stations_m.size());
  for (std::size_t i = 0; i < results.size(); ++i)
  {
    const double* v = &packed[i * packed_size];
    SectionFem& r = results[i];
    r.station_m = stations_m[i];
    r.approach_m = approaches_m[i];
    r.load_n_per_m = v[0];
    r.peak_pressure_pa = v[1];
    r.dofs = static_cast<std::int64_t>(v[2]);
    r.newton_iterations = static_cast<int>(v[3]);
    r.wall_s = v[4];
  }
  return results;
}
} // namespace rollcheck::fem

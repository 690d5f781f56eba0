#include "fem/scenes/slice_contact.h"
#include "fem/scenes/hertz_solve.h"
#include "fem/petsc_session.h"
#include "fem/share_out.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::fem
{
namespace
{
// A slice's result travels between ranks as these doubles.
constexpr std::size_t packed_size = 11;

std::vector<double> pack(const SliceFem& r)
{
  return {r.peak_pressure_pa,
          r.refined_peak_pressure_pa,
          r.half_width_m,
          r.hertz_peak_pressure_pa,
          r.hertz_half_width_m,
          static_cast<double>(r.dofs),
          static_cast<double>(r.refined_dofs),
          static_cast<double>(r.newton_iterations),
          static_cast<double>(r.krylov_iterations),
          r.wall_s,
          r.approach_m};
}

void unpack(const double* v, SliceFem& r)
{
  r.peak_pressure_pa = v[0];
  r.refined_peak_pressure_pa = v[1];
  r.half_width_m = v[2];
  r.hertz_peak_pressure_pa = v[3];
  r.hertz_half_width_m = v[4];
  r.dofs = static_cast<std::int64_t>(v[5]);
  r.refined_dofs = static_cast<std::int64_t>(v[6]);
  r.newton_iterations = static_cast<int>(v[7]);
  r.krylov_iterations = static_cast<int>(v[8]);
  r.wall_s = v[9];
  r.approach_m = v[10];
}

/// x > 0 to `digits` significant digits.
double rounded_to_significant_digits(double x, int digits)
{
  const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(x)));
  return std::round(x * scale) / scale;
}

SliceFem solve_slice(const SliceLoad& load, const SliceSettings& settings)
{
  SliceFem r;
  r.load = load;
  HertzSettings setup;
  setup.model = Model::plane_strain;
  setup.radius_m = load.radius_m;
  setup.youngs_modulus_pa = settings.youngs_modulus_pa;
  setup.poisson_ratio = settings.poisson_ratio;
  // gmsh's nodes follow the mesh sizes' last digits, and the sizes follow
  // b, so loads equal but for their last bits (a whole body's q through
  // MUMPS's parallel sums) meshed apart and their peaks differed by up to
  // 0.18 %. Solved at q to 9 significant digits (a change of at most 5e-10
  // in q, 2.5e-10 in p0) they share one mesh, unless q lies on a rounding
  // boundary.
  setup.force_n = rounded_to_significant_digits(load.load_n_per_m, 9); // per unit length
  setup.length_m = 1.0;
  setup.penalty_c = settings.penalty_c;
  setup.elastic_plane = settings.elastic_plane;
  setup.petsc_options = settings.petsc_options;
  setup.log_progress = false;
  setup.refine = settings.refine < 0 ? default_refine(Model::plane_strain, 1) : settings.refine;
  const HertzResult coarse = solve_hertz(MPI_COMM_SELF, setup);
  ++setup.refine;
  const HertzResult fine = solve_hertz(MPI_COMM_SELF, setup);
  r.peak_pressure_pa = coarse.max_nodal_pressure_pa;
  r.refined_peak_pressure_pa = fine.max_nodal_pressure_pa;
  r.half_width_m = coarse.contact_size_m;
  r.hertz_peak_pressure_pa = coarse.hertz.peak_pressure_pa;
  r.hertz_half_width_m = coarse.hertz.contact_size_m;
  r.approach_m = coarse.approach_m;
  r.dofs = coarse.dofs;
  r.refined_dofs = fine.dofs;
  r.newton_iterations = coarse.newton_iterations + fine.newton_iterations;
  r.krylov_iterations = coarse.krylov_iterations + fine.krylov_iterations;
  r.wall_s = coarse.wall_s + fine.wall_s;
  return r;
}
} // namespace

std::vector<SliceFem> solve_slices(MPI_Comm comm, std::span<const SliceLoad> slices, const SliceSettings& settings)
{
  ensure_petsc();
  const std::vector<double> packed = share_out(
      comm, slices.size(), packed_size, [&](std::size_t i) { return pack(solve_slice(slices[i], settings)); },
      [&](std::size_t i) {
        return fmt::format("slice at {:.6g} m (R = {:.6g} m, q = {:.6g} N/m)", slices[i].position_m,
                           slices[i].radius_m, slices[i].load_n_per_m);
      },
      "plane-strain slice solve", [&](std::size_t i) { return !(slices[i].load_n_per_m > 0); });
  std::vector<SliceFem> results(slices.size());
  for (std::size_t i = 0; i < slices.size(); ++i)
  {
    results[i].load = slices[i];
    unpack(&packed[i * packed_size], results[i]);
  }
  return results;
}
} // namespace rollcheck::fem

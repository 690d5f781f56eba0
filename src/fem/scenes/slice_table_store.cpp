// The slice table's nodes on disk (fem/scenes/slice_table_store.h).
#include "fem/scenes/slice_table_store.h"
#include "core/atomic_file.h"
#include "core/build_id.h"
#include "core/error.h"
#include "core/sha256.h"
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SliceLoad, position_m, radius_m, load_n_per_m)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SliceFem, load, peak_pressure_pa, refined_peak_pressure_pa, half_width_m,
                                   hertz_peak_pressure_pa, hertz_half_width_m, approach_m, dofs, refined_dofs,
                                   newton_iterations, krylov_iterations, wall_s)

namespace
{
/// The node's file: the hash of what its numbers depend on, every double by its bits.
std::filesystem::path node_path(const std::filesystem::path& folder, const SliceSettings& s, const SliceLoad& load)
{
  const std::string key = fmt::format("{}\n{:a} {:a} {} {:a} {:d}\n{}\n{:a} {:a} {:a}", build_id(), s.youngs_modulus_pa,
                                      s.poisson_ratio, s.refine, s.penalty_c, s.elastic_plane, s.petsc_options,
                                      load.position_m, load.radius_m, load.load_n_per_m);
  return folder / ("slice_" + sha256_hex(key) + ".json");
}
} // namespace

std::optional<SliceFem> read_stored_slice(const std::filesystem::path& folder, const SliceSettings& settings,
                                          const SliceLoad& load)
{
  std::ifstream in(node_path(folder, settings, load));
  if (!in)
    return std::nullopt;
  try
  {
    return nlohmann::json::parse(in).get<SliceFem>();
  }
  catch (const nlohmann::json::exception&)
  {
    return std::nullopt; // a file cut short or not ours: solved again
  }
}

bool store_slice(const std::filesystem::path& folder, const SliceSettings& settings, const SliceFem& fem)
{
  auto not_kept = [&](const std::string& why) {
    spdlog::warn("{} = {}: the slice table's nodes are not kept ({})", slice_table_folder_variable, folder.string(),
                 why);
    return false;
  };
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error)
    return not_kept(fmt::format("cannot create it: {}", error.message()));
  try
  {
    write_file_atomically(node_path(folder, settings, fem.load), nlohmann::json(fem).dump());
  }
  catch (const ComputationError& e) // the writer names the file and the system's reason
  {
    return not_kept(e.what());
  }
  return true;
}
} // namespace rollcheck::fem

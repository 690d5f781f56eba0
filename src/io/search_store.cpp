#include "io/search_store.h"
#include "io/hdf5_handle.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>
#include <hdf5.h>
#include <limits>

namespace rollcheck::io
{
namespace
{
nlohmann::json genome_json(const oracle::GenomeResult& r)
{
  nlohmann::json j = {{"theta_deg", r.genome.theta_deg}, {"offset", r.genome.offset},
                      {"ratio", r.genome.ratio},         {"n_circles", r.genome.n_circles},
                      {"valid", r.valid},                {"is_anchor_genome", r.is_anchor_genome}};
  if (!r.valid)
  {
    j["error"] = r.error;
    return j;
  }
  j["n_faces"] = r.n_faces;
  j["area_m2"] = r.area_m2;
  j["approximate"] = {{"cds", json_number(r.approximate_cds)},
                      {"contact_cv", json_number(r.approximate_contact_cv)},
                      {"max_contact_ratio", json_number(r.approximate_max_contact_ratio)},
                      {"rank", r.approximate_rank}};
  j["validated"] = r.validated;
  if (r.validated)
  {
    nlohmann::json rigid = {{"cds", json_number(r.rigid_cds)},
                            {"contact_cv", json_number(r.rigid_contact_cv)},
                            {"max_contact_ratio", json_number(r.rigid_max_contact_ratio)}};
    if (r.rigid_rank > 0)
      rigid["rank"] = r.rigid_rank;
    for (const auto& [name, value] : r.metrics)
      rigid[name] = json_number(value);
    j["rigid"] = rigid;
  }
  return j;
}
} // namespace

nlohmann::json search_summary(const oracle::SearchResult& result)
{
  const oracle::SearchSettings& o = result.options;
  nlohmann::json genomes = nlohmann::json::array();
  long valid = 0, validated = 0;
  for (const oracle::GenomeResult& r : result.genomes)
  {
    genomes.push_back(genome_json(r));
    valid += r.valid;
    validated += r.validated;
  }
  return {{"grid", std::string(oracle::name_of(o.grid))},
          {"approximate_steps", o.approximate_steps},
          {"validate_top", o.validate_top},
          {"validate_all", o.validate_all},
          {"matched_resolution", o.matched_resolution},
          {"points", o.points},
          {"anchor_points", result.anchor_points},
          {"radius_m", o.radius_m},
          {"compat", oracle::describe(o.compat)},
          {"threads", result.threads},
          {"n_genomes", result.genomes.size()},
          {"n_valid", valid},
          {"n_validated", validated},
          {"approximate_wall_s", result.approximate_wall_s},
          {"rigid_wall_s", result.rigid_wall_s},
          {"wall_s", result.wall_s},
          {"anchor", genome_json(result.anchor)},
          {"genomes", genomes}};
}

namespace
{
using hdf5::Handle;
using hdf5::check;

void write_doubles(hid_t parent, const std::string& name, const std::vector<double>& values)
{
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "create a dataspace for " + name);
  Handle set(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose, "create dataset " + name);
  check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + name);
}

void write_integers(hid_t parent, const std::string& name, const std::vector<long long>& values)
{
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "create a dataspace for " + name);
  Handle set(H5Dcreate2(parent, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose, "create dataset " + name);
  check(H5Dwrite(set, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + name);
}

void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& values)
{
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(type, H5T_VARIABLE), "make a variable-length string type");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "set UTF-8");
  const hsize_t n = values.size();
  std::vector<const char*> pointers;
  for (const std::string& s : values)
    pointers.push_back(s.c_str());
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "create a dataspace for " + name);
  Handle set(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "create dataset " + name);
  check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()), "write " + name);
}

void attribute(hid_t object, const std::string& name, const std::string& value)
{
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(type, value.size() + 1), "size a string type");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
  Handle a(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "create attribute " + name);
  check(H5Awrite(a, type, value.c_str()), "write attribute " + name);
}

void attribute(hid_t object, const std::string& name, double value)
{
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
  Handle a(H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
           "create attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

void attribute(hid_t object, const std::string& name, long long value)
{
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
  Handle a(H5Acreate2(object, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
           "create attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_LLONG, &value), "write attribute " + name);
}

/// The columns of /genomes (or, one row, /anchor).
void write_columns(hid_t group, const std::vector<const oracle::GenomeResult*>& rows,
                   const std::vector<std::string>& metric_names)
{
  constexpr double missing = std::numeric_limits<double>::quiet_NaN();
  auto column = [&](auto value) {
    std::vector<decltype(value(*rows.front()))> out;
    for (const oracle::GenomeResult* r : rows)
      out.push_back(value(*r));
    return out;
  };
  using Row = oracle::GenomeResult;
  // A score column: NaN where the score was not computed (`present` false).
  auto scores = [&](const char* name, bool Row::*present, double Row::*score) {
    write_doubles(group, name, column([&](const Row& r) { return r.*present ? r.*score : missing; }));
  };
  auto integers = [&](const char* name, auto Row::*member) {
    write_integers(group, name, column([&](const Row& r) { return static_cast<long long>(r.*member); }));
  };
  write_doubles(group, "theta_deg", column([](const Row& r) { return r.genome.theta_deg; }));
  write_doubles(group, "offset", column([](const Row& r) { return r.genome.offset; }));
  write_doubles(group, "ratio", column([](const Row& r) { return r.genome.ratio; }));
  write_integers(group, "n_circles", column([](const Row& r) { return static_cast<long long>(r.genome.n_circles); }));
  integers("valid", &Row::valid);
  integers("n_faces", &Row::n_faces);
  scores("area_m2", &Row::valid, &Row::area_m2);
  scores("approximate_cds", &Row::valid, &Row::approximate_cds);
  scores("approximate_contact_cv", &Row::valid, &Row::approximate_contact_cv);
  scores("approximate_max_contact_ratio", &Row::valid, &Row::approximate_max_contact_ratio);
  integers("approximate_rank", &Row::approximate_rank);
  integers("validated", &Row::validated);
  scores("rigid_cds", &Row::validated, &Row::rigid_cds);
  scores("rigid_contact_cv", &Row::validated, &Row::rigid_contact_cv);
  scores("rigid_max_contact_ratio", &Row::validated, &Row::rigid_max_contact_ratio);
  integers("rigid_rank", &Row::rigid_rank);
  for (const std::string& name : metric_names)
    write_doubles(group, name, column([&](const Row& r) {
                    for (const auto& [key, value] : r.metrics)
                      if (key == name)
                        return value;
                    return missing;
                  }));
  write_strings(group, "error", column([](const Row& r) { return r.error; }));
}
} // namespace

void write_search_hdf5(const oracle::SearchResult& result, const std::filesystem::path& path)
{
  std::vector<std::string> metric_names;
  for (const auto& [name, value] : result.anchor.metrics)
    metric_names.push_back(name);
  std::vector<const oracle::GenomeResult*> rows;
  for (const oracle::GenomeResult& r : result.genomes)
    rows.push_back(&r);
  const oracle::SearchSettings& o = result.options;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                fmt::format("create '{}'", path.string()));
    attribute(file, "layout", std::string("rollcheck-search-1"));
    attribute(file, "grid", std::string(oracle::name_of(o.grid)));
    attribute(file, "approximate_steps", static_cast<long long>(o.approximate_steps));
    attribute(file, "points", static_cast<long long>(o.points));
    attribute(file, "anchor_points", static_cast<long long>(result.anchor_points));
    attribute(file, "matched_resolution", static_cast<long long>(o.matched_resolution));
    attribute(file, "validate_top", static_cast<long long>(o.validate_top));
    attribute(file, "validate_all", static_cast<long long>(o.validate_all));
    attribute(file, "compat", oracle::describe(o.compat));
    attribute(file, "threads", static_cast<long long>(result.threads));
    attribute(file, "approximate_wall_s", result.approximate_wall_s);
    attribute(file, "rigid_wall_s", result.rigid_wall_s);
    attribute(file, "wall_s", result.wall_s);
    {
      Handle genomes(H5Gcreate2(file, "genomes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create /genomes");
      if (!rows.empty())
        write_columns(genomes, rows, metric_names);
    }
    Handle anchor(H5Gcreate2(file, "anchor", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create /anchor");
    write_columns(anchor, {&result.anchor}, metric_names);
    check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush " + path.string());
  });
}
} // namespace rollcheck::io

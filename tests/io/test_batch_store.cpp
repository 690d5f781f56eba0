// The HDF5 results store: the documented JSON -> HDF5 mapping, read back with
// the HDF5 C API (independently of the writer); atomic replacement; and the
// report drawn from a store filled with the reference code's own outputs.
#include "core/error.h"
#include "io/hdf5_test_reader.h"
#include "io/results_store.h"
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace rollcheck;
namespace fs = std::filesystem;

namespace
{
const fs::path reference_meshes = ROLLCHECK_REFERENCE_MESH_DIR;
const fs::path reference_data = ROLLCHECK_REFERENCE_DATA_DIR;

fs::path fresh_folder(const std::string& name)
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / "batch_store" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

nlohmann::json sample_record()
{
  return {
      {"status", "ok"},
      {"hash", "0123456789abcdef"},
      {"wall_s", 1.5},
      {"mpi_ranks", 1},
      {"parameters", {{"kind", "demo"}, {"radius_m", 0.01}, {"points", 400}, {"flag", true}, {"mesh_file", ""}}},
      {"summary",
       {{"n_faces", 1198},
        {"cds", 8.17e-7},
        {"convex", true},
        {"body", "oloid"},
        {"fds", nullptr},
        {"counts", {0, 3, 5}},
        {"centroids", {{0.0, 1.0, 2.0}, {3.0, 4.0, 5.0}}},
        {"touched", {true, false}},
        {"mixed_numbers", {1, 2.5}},
        {"flags", {"penalty_error_dominates", "coarse"}},
        {"ragged", {{1, 2}, {3}}},
        {"orientations", {{{"peak_pa", 2.0e9}}, {{"peak_pa", 1.9e9}}}},
        {"empty", nlohmann::json::array()},
        {"profile", {{"r_m", {0.0, 1e-5}}, {"p_pa", {2.1e9, 2.0e9}}}},
        {"a/b", 1}}},
      {"files", {"cases/0123456789abcdef/fields.xdmf"}}};
}
} // namespace

TEST(ResultsStore, MapsSummaryJsonToDatasetsAndGroupsAsDocumented)
{
  const fs::path store = fresh_folder("mapping") / "results.h5";
  io::write_results_store(store, {{"oloid", sample_record()}}, {{"n_cases", 1}});
  const Hdf5TestReader r(store);
  ASSERT_TRUE(r.ok());
  const std::string s = "/cases/oloid/summary/";
  // Scalars: typed scalar datasets.
  EXPECT_EQ(r.type_class(s + "n_faces"), H5T_INTEGER);
  EXPECT_EQ(r.numbers<std::int64_t>(s + "n_faces", H5T_NATIVE_INT64), std::vector<std::int64_t>{1198});
  EXPECT_EQ(r.type_class(s + "cds"), H5T_FLOAT);
  EXPECT_EQ(r.numbers<double>(s + "cds", H5T_NATIVE_DOUBLE), std::vector<double>{8.17e-7});
  EXPECT_EQ(r.type_class(s + "convex"), H5T_ENUM);
  EXPECT_EQ(r.strings(s + "body"), std::vector<std::string>{"oloid"});
  EXPECT_EQ(r.space_class(s + "fds"), H5S_NULL);
  // Rectangular numeric arrays: n-d datasets of the right type.
  EXPECT_EQ(r.type_class(s + "counts"), H5T_INTEGER);
  EXPECT_EQ(r.numbers<std::int64_t>(s + "counts", H5T_NATIVE_INT64), (std::vector<std::int64_t>{0, 3, 5}));
  EXPECT_EQ(r.shape(s + "centroids"), (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(r.numbers<double>(s + "centroids", H5T_NATIVE_DOUBLE), (std::vector<double>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(r.type_class(s + "touched"), H5T_ENUM);
  EXPECT_EQ(r.type_class(s + "mixed_numbers"), H5T_FLOAT);
  EXPECT_EQ(r.shape(s + "empty"), std::vector<hsize_t>{0});
  EXPECT_EQ(r.strings(s + "flags"), (std::vector<std::string>{"penalty_error_dominates", "coarse"}));
  // Other arrays: groups of indexed members, flagged json_array.
  EXPECT_EQ(r.number_attribute<std::int64_t>(s + "ragged", "json_array", H5T_NATIVE_INT64), 1);
  EXPECT_EQ(r.numbers<std::int64_t>(s + "ragged/1", H5T_NATIVE_INT64), std::vector<std::int64_t>{3});
  EXPECT_EQ(r.numbers<double>(s + "orientations/1/peak_pa", H5T_NATIVE_DOUBLE), std::vector<double>{1.9e9});
  // Objects: groups; '/' in a key becomes '_'.
  EXPECT_EQ(r.numbers<double>(s + "profile/p_pa", H5T_NATIVE_DOUBLE), (std::vector<double>{2.1e9, 2.0e9}));
  EXPECT_TRUE(r.exists(s + "a_b"));
}

TEST(ResultsStore, NumbersCarryUnitsAndInfinitiesAreFloats)
{
  nlohmann::json record = sample_record();
  record["summary"]["tds"] = "inf";
  record["summary"]["bounds_pa"] = {"-inf", 1.0, "inf"};
  record["case_text"] = "[scene]\nkind = \"mesh\"\n";
  record["summary"]["sliding"] = {{"max_speed_m_s", 0.4}};
  record["summary"]["curvature"] = {{"face_mean_curvature_mean_per_m", 1.2}, {"face_gaussian_curvature_mean_per_m2", 0.8}};
  record["summary"]["convergence"] = {{"cds", {{50, 0.1}, {100, 0.05}}}};
  record["summary"]["flags"] = nlohmann::json::array();
  const fs::path store = fresh_folder("units") / "results.h5";
  io::write_results_store(store, {{"oloid", record}}, {{"n_cases", 1}});
  const Hdf5TestReader r(store);
  const std::string s = "/cases/oloid/summary/";
  // Units the record's schema declares (io/result_fields.h), "1" for a pure
  // number, on every numeric dataset; compound units whole, not their last word.
  EXPECT_EQ(r.string_attribute(s + "profile/p_pa", "units"), "Pa");
  EXPECT_EQ(r.string_attribute(s + "sliding/max_speed_m_s", "units"), "m/s");
  EXPECT_EQ(r.string_attribute(s + "curvature/face_mean_curvature_mean_per_m", "units"), "1/m");
  EXPECT_EQ(r.string_attribute(s + "curvature/face_gaussian_curvature_mean_per_m2", "units"), "1/m^2");
  // A table has its columns; an empty list of flags is text, not numbers.
  EXPECT_EQ(r.string_attribute(s + "convergence/cds", "columns"), "samples, score");
  EXPECT_EQ(r.type_class(s + "flags"), H5T_STRING);
  EXPECT_EQ(r.string_attribute(s + "profile/r_m", "units"), "m");
  EXPECT_EQ(r.string_attribute(s + "cds", "units"), "1");
  EXPECT_EQ(r.string_attribute(s + "n_faces", "units"), "1");
  // The JSON "inf" is a float in the store, alone and in arrays.
  EXPECT_EQ(r.type_class(s + "tds"), H5T_FLOAT);
  EXPECT_EQ(r.numbers<double>(s + "tds", H5T_NATIVE_DOUBLE), std::vector<double>{INFINITY});
  EXPECT_EQ(r.numbers<double>(s + "bounds_pa", H5T_NATIVE_DOUBLE), (std::vector<double>{-INFINITY, 1.0, INFINITY}));
  // The case file's text is stored with its result.
  EXPECT_EQ(r.string_attribute("/cases/oloid", "case_text"), "[scene]\nkind = \"mesh\"\n");
}

TEST(ResultsStore, RecordFieldsAndParametersAreTypedAttributes)
{
  const fs::path store = fresh_folder("attributes") / "results.h5";
  io::write_results_store(store, {{"oloid", sample_record()}}, {{"n_cases", 1}});
  const Hdf5TestReader r(store);
  EXPECT_EQ(r.string_attribute("/", "layout"), "rollcheck-results-1");
  EXPECT_EQ(r.number_attribute<std::int64_t>("/", "n_cases", H5T_NATIVE_INT64), 1);
  EXPECT_EQ(r.string_attribute("/cases/oloid", "status"), "ok");
  EXPECT_EQ(r.string_attribute("/cases/oloid", "hash"), "0123456789abcdef");
  EXPECT_EQ(r.number_attribute<double>("/cases/oloid", "wall_s", H5T_NATIVE_DOUBLE), 1.5);
  EXPECT_EQ(r.number_attribute<double>("/cases/oloid/parameters", "radius_m", H5T_NATIVE_DOUBLE), 0.01);
  EXPECT_EQ(r.number_attribute<std::int64_t>("/cases/oloid/parameters", "points", H5T_NATIVE_INT64), 400);
  EXPECT_EQ(r.string_attribute("/cases/oloid/parameters", "mesh_file"), "");
  EXPECT_EQ(r.strings("/cases/oloid/files"), std::vector<std::string>{"cases/0123456789abcdef/fields.xdmf"});
}

TEST(ResultsStore, KeepsTheBatchOrderOfCases)
{
  const fs::path store = fresh_folder("order") / "results.h5";
  io::write_results_store(store, {{"zeta", sample_record()}, {"alpha", sample_record()}, {"mid", sample_record()}},
                          nlohmann::json::object());
  EXPECT_EQ(Hdf5TestReader(store).members_in_creation_order("/cases"),
            (std::vector<std::string>{"zeta", "alpha", "mid"}));
}

TEST(ResultsStore, AFailedWriteLeavesThePreviousStoreAndNoTemporaryFile)
{
  const fs::path dir = fresh_folder("atomic");
  const fs::path store = dir / "results.h5";
  io::write_results_store(store, {{"first", sample_record()}}, nlohmann::json::object());
  std::ifstream before_in(store, std::ios::binary);
  const std::string before((std::istreambuf_iterator<char>(before_in)), std::istreambuf_iterator<char>());
  // Two cases of one name: HDF5 refuses the second group half-way through the file.
  EXPECT_THROW(io::write_results_store(store, {{"twin", sample_record()}, {"twin", sample_record()}},
                                       nlohmann::json::object()),
               ComputationError);
  std::ifstream after_in(store, std::ios::binary);
  const std::string after((std::istreambuf_iterator<char>(after_in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(before, after);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  EXPECT_THROW(io::write_results_store(dir / "missing" / "results.h5", {}, nlohmann::json::object()), InputError);
  EXPECT_FALSE(fs::exists(dir / "missing"));
}

TEST(ResultsStore, IsRecognisedByItsLayoutAlone)
{
  // A batch adopts a results.h5 only if rollcheck wrote it (batch_run.cpp).
  const fs::path dir = fresh_folder("recognised");
  io::write_results_store(dir / "results.h5", {{"a", sample_record()}}, nlohmann::json::object());
  EXPECT_TRUE(io::is_results_store(dir / "results.h5"));
  std::ofstream(dir / "text.h5") << "the user's notes";
  EXPECT_FALSE(io::is_results_store(dir / "text.h5"));
  const hid_t other = H5Fcreate((dir / "other.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(other, 0);
  H5Fclose(other);
  EXPECT_FALSE(io::is_results_store(dir / "other.h5"));
  EXPECT_FALSE(io::is_results_store(dir / "missing.h5"));
}

TEST(ResultsStore, ReportDrawsTheReferenceCodesOwnConvergenceAndPerFaceContacts)
{
  // The published code's outputs (tests/data/reference) as two oracle-like
  // records: its rigid-body CDS snapshots and per-face contact counts with
  // face areas and centroids, and the mesh they were counted on. The report
  // must draw both plots from them.
  std::ifstream outputs_in(reference_data / "reference_outputs.json");
  const nlohmann::json outputs = nlohmann::json::parse(outputs_in);
  std::vector<io::StoreEntry> entries;
  for (const std::string body : {"oloid", "cylinder"})
  {
    std::ifstream per_face_in(reference_data / ("perface_" + body + ".json"));
    const nlohmann::json per_face = nlohmann::json::parse(per_face_in);
    const nlohmann::json& rigid = outputs.at("geometries").at(body).at("rigid");
    entries.push_back({body,
                       {{"status", "ok"},
                        {"kind", "oracle"},
                        {"wall_s", rigid.at("wall_s")},
                        {"parameters",
                         {{"kind", "oracle"},
                          {"body", body},
                          {"mesh_file", (reference_meshes / (body + "_reference.obj")).string()}}},
                        {"summary",
                         {{"oracle", "rigid"},
                          {"cds", rigid.at("cds")},
                          {"n_samples", rigid.at("n_samples")},
                          {"n_faces", per_face.at("face_areas").size()},
                          {"convergence", {{"cds", rigid.at("convergence")}}},
                          {"per_face",
                           {{"face_areas_m2", per_face.at("face_areas")},
                            {"face_centroids_m", per_face.at("face_centroids")},
                            {"contact_counts", per_face.at("rigid_contact_counts")}}}}}}});
  }
  const fs::path dir = fresh_folder("report");
  io::write_results_store(dir / "results.h5", entries, nlohmann::json::object());
  const std::string command = std::string(ROLLCHECK_BINARY) + " -q report --from " + (dir / "results.h5").string()
                              + " > " + (dir / "report_stdout.txt").string();
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream md_in(dir / "report" / "report.md");
  std::stringstream md;
  md << md_in.rdbuf();
  EXPECT_NE(md.str().find("](cds_convergence.png)"), std::string::npos) << md.str();
  EXPECT_NE(md.str().find("](contact_density_0.png)"), std::string::npos);
  EXPECT_NE(md.str().find("](contact_density_1.png)"), std::string::npos);
  EXPECT_EQ(md.str().find("FAILED to draw"), std::string::npos);
  for (const char* png : {"cds_convergence.png", "contact_density_0.png", "contact_density_1.png"})
    EXPECT_GT(fs::file_size(dir / "report" / png), 10000u) << png;
  std::ifstream html_in(dir / "report" / "report.html");
  std::stringstream html;
  html << html_in.rdbuf();
  EXPECT_NE(html.str().find("data:image/png;base64,"), std::string::npos);
}

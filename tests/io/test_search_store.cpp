// The search's JSON summary and HDF5 file: read back with the HDF5 C API.
#include "io/hdf5_test_reader.h"
#include "io/search_store.h"
#include "core/error.h"
#include <filesystem>
#include <gtest/gtest.h>
#include <hdf5.h>

namespace
{
using namespace rollcheck;

TEST(SearchStore, HdfFileAndJsonCarryTheSameNumbers)
{
  oracle::SearchSettings o;
  o.validate_top = 2;
  o.revalidation_metrics = [](const auto&, const auto&, const oracle::Trajectory& t) {
    return oracle::NamedScores{{"samples", static_cast<double>(t.size())}};
  };
  const oracle::SearchResult result = oracle::parametric_search(o);
  const std::filesystem::path dir = ROLLCHECK_TEST_TMP;
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "search_store.h5";
  io::write_search_hdf5(result, path);
  const nlohmann::json summary = io::search_summary(result);

  const Hdf5TestReader file(path);
  ASSERT_TRUE(file.ok());
  const auto theta = file.doubles("/genomes/theta_deg");
  const auto cds = file.doubles("/genomes/approximate_cds");
  const auto rigid = file.doubles("/genomes/rigid_cds");
  const auto samples = file.doubles("/genomes/samples");
  ASSERT_EQ(theta.size(), 45u);
  ASSERT_EQ(summary["genomes"].size(), 45u);
  long validated = 0;
  for (std::size_t i = 0; i < theta.size(); ++i)
  {
    const nlohmann::json& g = summary["genomes"][i];
    EXPECT_EQ(theta[i], g["theta_deg"].get<double>());
    EXPECT_EQ(cds[i], g["approximate"]["cds"].get<double>());
    if (g["validated"].get<bool>())
    {
      ++validated;
      EXPECT_EQ(rigid[i], g["rigid"]["cds"].get<double>());
      EXPECT_EQ(samples[i], 600.0);
    }
    else
      EXPECT_TRUE(std::isnan(rigid[i]) && std::isnan(samples[i])); // not revalidated
  }
  EXPECT_EQ(validated, 2);
  EXPECT_EQ(file.doubles("/anchor/rigid_cds").at(0), summary["anchor"]["rigid"]["cds"].get<double>());
}

TEST(SearchStore, JsonNumbersAreFiniteOrTheStringInf)
{
  EXPECT_EQ(json_number(1.5), nlohmann::json(1.5));
  EXPECT_EQ(json_number(std::numeric_limits<double>::infinity()), nlohmann::json("inf"));
  EXPECT_THROW(json_number(std::nan("")), ComputationError);
}
} // namespace

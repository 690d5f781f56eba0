// The paper-compatible oracles against the reference code's own outputs
// (tests/data/reference: reference_outputs.json, perface_*.json), on the exact
// meshes it scored.
#include "geometry/read_mesh.h"
#include "oracle/approximate_oracle.h"
#include "oracle/contact_distribution.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace
{
using namespace rollcheck;
const std::string reference_dir = std::string(ROLLCHECK_REFERENCE_DATA_DIR);

const nlohmann::json& reference()
{
  static const nlohmann::json j = nlohmann::json::parse(std::ifstream(reference_dir + "/reference_outputs.json"));
  return j;
}

nlohmann::json perface(const std::string& name)
{
  return nlohmann::json::parse(std::ifstream(reference_dir + "/perface_" + name + ".json"));
}

geometry::SurfaceMesh reference_mesh(const std::string& name)
{
  const std::string file = name == "sphere" ? "sphere_icosphere3.obj" : name + "_reference.obj";
  return geometry::read_mesh(std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/" + file);
}

double relative(double ours, double theirs) { return std::abs(ours - theirs) / std::abs(theirs); }

class ReferenceBody : public ::testing::TestWithParam<std::string>
{
};

TEST_P(ReferenceBody, ApproximateOracleMatchesReference)
{
  const std::string name = GetParam();
  const nlohmann::json& ref = reference()["geometries"][name]["approx"];
  const auto compat = oracle::PaperCompat::reference();
  const oracle::RollingBody body = oracle::make_rolling_body(reference_mesh(name), compat);
  const oracle::Trajectory trajectory = oracle::approximate_oracle(body, {}, compat);
  const oracle::ContactDistribution cds = oracle::contact_distribution(trajectory, body.face_areas, 50);
  EXPECT_LT(relative(cds.summary.score, ref["cds"].get<double>()), 1e-9) << cds.summary.score;
  EXPECT_LT(relative(cds.summary.cv, ref["contact_cv"].get<double>()), 1e-9);
  EXPECT_LT(relative(cds.summary.max_mean_ratio, ref["max_contact_ratio"].get<double>()), 1e-9);
  EXPECT_EQ(cds.summary.faces_with, ref["faces_with_contact"].get<long>());
  ASSERT_EQ(cds.convergence.size(), ref["convergence"].size());
  for (std::size_t i = 0; i < cds.convergence.size(); ++i)
  {
    EXPECT_EQ(cds.convergence[i].first, ref["convergence"][i][0].get<long>());
    EXPECT_LT(relative(cds.convergence[i].second, ref["convergence"][i][1].get<double>()), 1e-9);
  }
  if (name != "sphere")
  {
    const nlohmann::json pf = perface(name);
    const auto counts = pf["approx_contact_counts"].get<std::vector<double>>();
    ASSERT_EQ(counts.size(), static_cast<std::size_t>(cds.counts.size()));
    for (std::size_t f = 0; f < counts.size(); ++f)
      EXPECT_EQ(cds.counts[static_cast<Eigen::Index>(f)], counts[f]) << "face " << f;
  }
}

TEST_P(ReferenceBody, RigidBodyRotationsOfRunOneMatchReference)
{
  const std::string name = GetParam();
  const nlohmann::json& checkpoints = reference()["geometries"][name]["rigid"]["run1_R_checkpoints"];
  const auto compat = oracle::PaperCompat::reference();
  const oracle::RollingBody body = oracle::make_rolling_body(reference_mesh(name), compat);
  const oracle::RigidBodySettings options;
  const auto rotations = oracle::rigid_body_rotations(body, options.initial_spins[0], 1001, options, compat);
  for (const int step : {0, 1, 10, 100, 1000})
  {
    const auto expected = checkpoints[std::to_string(step)];
    double worst = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        worst = std::max(worst, std::abs(rotations[static_cast<std::size_t>(step)](i, j) - expected[i][j].get<double>()));
    EXPECT_LT(worst, 1e-9) << name << " step " << step;
    RecordProperty(name + "_step_" + std::to_string(step) + "_max_abs_diff", std::to_string(worst));
    std::cout << name << " run 1, step " << step << ": max |R - R_ref| = " << worst << "\n";
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, ReferenceBody, ::testing::Values("oloid", "cylinder", "sphere"));
} // namespace

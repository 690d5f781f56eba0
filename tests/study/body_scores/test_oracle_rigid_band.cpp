// Rigid-body scores against the reference outputs. The rigid-body runs are
// chaotic (tests/data/reference/README.md): a 1e-12 rad/s change of the initial
// spin moves the final orientations by ~1e-3 and the scores by up to ~10 %.
// The reference's scores are therefore compared within the band of that
// sensitivity, measured on our own oracle by study::body_scores::spin_nudge_band (every
// run's initial spin nudged by +-1e-12 rad/s along x, y and z in turn: 6
// nudged evaluations besides the nominal one); the band half-width of a score
// is its largest |nudged - nominal|. A reference score passes when it lies
// within that half-width of our nominal score, or, where no nudge changes any
// contact (the cylinder's CDS: half-width 0), agrees with it to rounding
// (1e-12 relative). Mean peak pressure and stress CV, which average over all
// samples, must agree to 0.5 %.
#include "study/body_scores/paper_quirks.h"
#include "study/body_scores/score_body.h"
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>

namespace
{
using namespace rollcheck;
const std::string reference_dir = std::string(ROLLCHECK_REFERENCE_DATA_DIR);

class RigidBand : public ::testing::TestWithParam<std::string>
{
};

TEST_P(RigidBand, ScoresLieWithinTheNudgeBand)
{
  const std::string name = GetParam();
  const auto ref = nlohmann::json::parse(std::ifstream(reference_dir + "/reference_outputs.json"))["geometries"][name];
  study::body_scores::ScoreBodySettings settings; // the rigid-body oracle and every score, at the preprint's values
  settings.body.mesh_file = std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/" + name + "_reference.obj";
  settings.compat = oracle::PaperCompat::reference();
  const study::body_scores::SpinNudgeBand band = study::body_scores::spin_nudge_band(settings);
  ASSERT_EQ(band.nudged.size(), 6u);
  // The reference's value of each column of the quirk table (FDS: a number or "inf").
  const std::map<std::string_view, nlohmann::json> expected = {
      {"CDS", ref["rigid"]["cds"]},       {"SDS", ref["hertz"]["sds"]},
      {"TDS", ref["thermal"]["tds"]},     {"WDS_vol", ref["wear"]["wds_vol"]},
      {"WDS_depth", ref["wear"]["wds_depth"]}, {"FDS", ref["fatigue"]["fds"]}};
  for (const study::body_scores::ScoreColumn& column : study::body_scores::score_columns())
  {
    const auto it = expected.find(column.key);
    if (it == expected.end())
      continue;
    const double ours = *column.value(band.nominal);
    if (!it->second.is_number()) // FDS of the cylinder: no stress above the endurance limit
    {
      EXPECT_TRUE(std::isinf(ours)) << column.key;
      continue;
    }
    const double theirs = it->second.get<double>();
    const double half_width = study::body_scores::half_width(band, column);
    std::cout << name << " " << column.key << ": ours " << ours << ", reference " << theirs << ", |diff| "
              << std::abs(ours - theirs) << ", nudge band +-" << half_width << " (" << 100 * half_width / theirs
              << " %)\n";
    EXPECT_LE(std::abs(ours - theirs), std::max(half_width, 1e-12 * std::abs(theirs))) << column.key;
  }
  const double mean_peak = ref["hertz"]["mean_peak_MPa"].get<double>() * 1e6;
  const double stress_cv = ref["hertz"]["stress_cv"].get<double>();
  EXPECT_LT(std::abs(band.nominal.peak_pressure_pa.mean / mean_peak - 1), 0.005) << band.nominal.peak_pressure_pa.mean;
  EXPECT_LT(std::abs(band.nominal.peak_pressure_pa.cv / stress_cv - 1), 0.005) << band.nominal.peak_pressure_pa.cv;
}

INSTANTIATE_TEST_SUITE_P(Meshes, RigidBand, ::testing::Values("oloid", "cylinder"));
} // namespace

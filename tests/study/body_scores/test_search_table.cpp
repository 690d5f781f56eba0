// The ranked table of the parametric search (study/body_scores/search_table.h)
// on a made-up result: the header counts the valid and revalidated genomes,
// the anchor comes first, the valid genomes follow by approximate rank up to
// the rows asked for, the grid's own (90, 1, 1) genome is starred, ratios are
// to the anchor, and a revalidated genome shows its rigid-body scores.
#include "study/body_scores/search_table.h"
#include <gtest/gtest.h>
#include <sstream>
#include <vector>

using namespace rollcheck;

namespace
{
oracle::GenomeResult genome(double theta, double approximate_cds, long rank)
{
  oracle::GenomeResult g;
  g.genome.theta_deg = theta;
  g.valid = rank > 0;
  g.approximate_cds = approximate_cds;
  g.approximate_rank = rank;
  return g;
}

oracle::SearchResult made_up_search()
{
  oracle::SearchResult r;
  r.options.grid = oracle::SearchGrid::quick;
  r.anchor = genome(90, 2e-6, 0);
  r.anchor.rigid_cds = 4e-6;
  r.anchor_points = 400;
  r.genomes = {genome(60, 3e-6, 2), genome(75, 1e-6, 1), genome(105, 0, 0)};
  r.genomes[0].is_anchor_genome = true;
  r.genomes[1].validated = true;
  r.genomes[1].rigid_cds = 2e-6;
  r.genomes[1].rigid_rank = 1;
  r.genomes[1].metrics = {{"sds", 5e-6}, {"tds", 6e-6}, {"fds", 7e-6}};
  return r;
}

std::vector<std::string> lines(const std::string& text)
{
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    out.push_back(line);
  return out;
}
} // namespace

TEST(SearchTable, RanksTheValidGenomesBelowTheAnchor)
{
  const std::vector<std::string> t = lines(study::body_scores::ranked_table(made_up_search(), 5));
  ASSERT_EQ(t.size(), 6u);
  EXPECT_TRUE(t[0].starts_with("quick grid: 3 genomes, 2 valid, 1 revalidated;")) << t[0];
  EXPECT_NE(t[1].find("approx CDS"), std::string::npos) << t[1];
  EXPECT_TRUE(t[2].starts_with("400p   90.0")) << t[2];
  EXPECT_TRUE(t[3].starts_with("   1   75.0")) << t[3];
  EXPECT_NE(t[3].find(" 1e-06   0.500       2e-06   0.500     1       5e-06       6e-06       7e-06"), std::string::npos)
      << t[3];
  EXPECT_TRUE(t[4].starts_with("  2*   60.0")) << t[4];
  EXPECT_TRUE(t[4].ends_with("   1.500 ")) << t[4];
  EXPECT_TRUE(t[5].starts_with("(first row: the anchor oloid at 400 points per circle;")) << t[5];
}

TEST(SearchTable, PrintsTheRowsAskedFor)
{
  const std::vector<std::string> t = lines(study::body_scores::ranked_table(made_up_search(), 1));
  ASSERT_EQ(t.size(), 5u);
  EXPECT_TRUE(t[3].starts_with("   1   75.0")) << t[3];
}

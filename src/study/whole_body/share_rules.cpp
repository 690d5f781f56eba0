// The whole-body check's share rules (study/whole_body/share_rules.h).
#include "study/whole_body/share_rules.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include <chrono>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::study::whole_body
{
namespace
{
/// The locus's rule: nothing to solve.
LineLoad locus_rule(const CheckContext& context, WholeBodyCheck&)
{
  return [&context](double f) { return context.locus_load_at(f); };
}

/// The sections' rule: every section meshed as the whole body's interior
/// (without its end refinement), started from line contact under the
/// locus's q at the centre of mass's foot.
LineLoad sections_rule(const CheckContext& context, WholeBodyCheck& check)
{
  const WholeBodyCheckSettings& s = context.settings;
  const double L = context.length_m(), c = context.centre_of_pressure();
  fem::SectionSettings section;
  section.youngs_modulus_pa = s.youngs_modulus_pa;
  section.poisson_ratio = s.poisson_ratio;
  section.penalty_c = s.penalty_c;
  const RigidStart rigid = rigid_start(context, context.locus_load_at(c));
  section.first_shift_m = rigid.shift_m;
  SectionShareSettings rule;
  rule.stations = s.rule_stations;
  fem::WholeBodySizes interior = context.sizing.sizes;
  interior.edge_m = interior.edge_zone_m = 0;
  // The mapped body's pose, or for the extruded cylinder one built for its sections.
  const fem::MappedBodyPose pose = context.pose ? *context.pose : mapped_pose(context);
  check.section_share
      = section_share(context.comm, pose, s.normal_load_n, c * L, rigid.approach_m, interior, section, rule);
  const SectionShare& solved = *check.section_share;
  if (context.log)
    spdlog::info("section load rule: {} sections of {} DOFs, {} passes, F {:.6g} N, centre of pressure {:.6f} L, "
                 "{:.1f} s",
                 s.rule_stations, solved.section_dofs, solved.passes, solved.force_n, solved.centre_of_pressure_m / L,
                 solved.wall_s);
  return [solved, L](double f) { return solved.load_at(f * L); };
}

/// The coarse body's rule: the whole body at the coarse sizes, started from
/// line contact under the locus's q at the centre of mass's foot.
LineLoad coarse_body_rule(const CheckContext& context, WholeBodyCheck& check)
{
  const WholeBodyCheckSettings& s = context.settings;
  const auto clock = std::chrono::steady_clock::now();
  fem::WholeBodySizes coarse = context.sizing.sizes;
  coarse.contact_m = context.sizing.smallest_b / s.rule_contact_elements;
  coarse.end_layer_m = s.rule_end_layer * context.sizing.smallest_end_b;
  coarse.edge_m = coarse.edge_zone_m = 0;
  BodySolve solved = solve_body(context, coarse, context.locus_load_at(context.centre_of_pressure()));
  check.coarse_body = WholeBodyCheck::CoarseBody{coarse, solved.node_planes, std::move(solved.fem),
                                                 fem::wall_seconds_since(context.comm, clock)};
  const WholeBodyCheck::CoarseBody& body = *check.coarse_body;
  if (context.log)
    spdlog::info("coarse body load rule: {} DOFs, {:.1f} s", body.fem.dofs, body.wall_s);
  return [x = body.fem.plane_x_m, q = body.fem.plane_load_n_per_m, L = context.length_m()](double f) {
    return fem::interpolate_planes(x, q, f * L);
  };
}
} // namespace

const ShareRuleStrategy& share_rule_strategy(ShareRule rule)
{
  static const ShareRuleStrategy locus{"locus", false, locus_rule};
  static const ShareRuleStrategy sections{"sections", true, sections_rule};
  static const ShareRuleStrategy coarse_body{"coarse-body", true, coarse_body_rule};
  switch (rule)
  {
  case ShareRule::sections:
    return sections;
  case ShareRule::coarse_body:
    return coarse_body;
  case ShareRule::locus:
    break;
  }
  return locus;
}

void require_rule_applies(const ShareRuleStrategy& rule, const CheckContext& context)
{
  const WholeBodyOrientation& o = context.orientation;
  if (rule.softens_ends && (o.loaded_from > 0 || o.loaded_to < 1))
    throw InputError(fmt::format("share_rule {}: direction {} deg loads only part of the ruling (c = {:.4f} outside "
                                 "[1/3, 2/3]); the rule is matched to the end models at both rim ends, loaded end to "
                                 "end",
                                 rule.name, context.settings.direction_deg, o.centre_of_pressure));
}

bool softens_ends(ShareRule rule) { return share_rule_strategy(rule).softens_ends; }
} // namespace rollcheck::study::whole_body

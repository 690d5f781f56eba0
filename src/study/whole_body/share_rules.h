#pragma once
// The whole-body check's share rules (ShareRule, study/whole_body/whole_body_check.h):
// how F is spread along the ruling for the slices and the end models, each
// a strategy chosen once per check (share_rule_strategy) that the stages
// read through its line load q(f) and whether it softens the ends:
//  - locus: the contact locus's no-tension linear rule (oracle/line_load.h,
//    fem-sds's): q(f) = line_load(F, c, L, f); solves nothing;
//  - sections: the body's own sections under one rigid approach and tilt
//    (study/whole_body/section_share.h), linear between its stations;
//  - coarse-body: the whole body meshed coarsely (b_min / rule_contact_elements
//    across the ruling, end layers rule_end_layer b_end, no refinement at
//    the ends), its line load on each node plane, linear between them.
// Internal to the check; not part of the wing's umbrella header.
#include "study/whole_body/check_context.h"
#include <string_view>

namespace rollcheck::study::whole_body
{
struct ShareRuleStrategy
{
  std::string_view name; ///< the option's and the JSON's spelling
  /// Its line load already falls towards the ends (softens_ends): the end
  /// models are matched to it d_m inside the ends, and it needs a ruling
  /// loaded end to end.
  bool softens_ends;
  /// Solves what the rule is read from (nothing, the sections, the coarse
  /// body), records it in `check` (section_share, coarse_body) and returns
  /// its q(f).
  LineLoad (*solve)(const CheckContext& context, WholeBodyCheck& check);
};

const ShareRuleStrategy& share_rule_strategy(ShareRule rule);

/// InputError where `rule` softens the ends but the orientation loads only
/// part of the ruling (c outside [1/3, 2/3]): such a rule is matched to the
/// end models at both rim ends.
void require_rule_applies(const ShareRuleStrategy& rule, const CheckContext& context);
} // namespace rollcheck::study::whole_body

// The load of one ruling under a load rule (contact/ruling_load.h).
#include "contact/ruling_load.h"
#include "oracle/line_load.h"
#include <algorithm>

namespace rollcheck::contact
{
const NamedValues<LoadRule>& load_rule_names()
{
  static const NamedValues<LoadRule> names = {{"static", LoadRule::static_through_centre_of_mass},
                                              {"dynamic", LoadRule::dynamic},
                                              {"uniform", LoadRule::uniform}};
  return names;
}

double RulingLoad::line_load(double length_m, double f) const
{
  if (uniform)
    return normal_n / length_m;
  return oracle::line_load(normal_n, centre, length_m, f);
}

RulingLoad ruling_resultant(const oracle::RollingSample& sample, LoadRule rule, double normal_load_n,
                            const RollingBodyMass& body)
{
  RulingLoad load;
  const Eigen::Vector3d along = sample.contact_end_m - sample.contact_start_m;
  switch (rule)
  {
  case LoadRule::uniform:
    load.normal_n = normal_load_n;
    load.uniform = true;
    break;
  case LoadRule::static_through_centre_of_mass:
    load.normal_n = normal_load_n;
    load.centre = (body.centre_of_mass_m - sample.contact_start_m).dot(along) / along.squaredNorm();
    break;
  case LoadRule::dynamic:
    load.normal_n = normal_load_n * sample.normal_force_n / (body.mass_kg * body.gravity_m_s2);
    load.centre = sample.centre_of_pressure;
    break;
  }
  return load;
}

RulingLoad ruling_load(const oracle::RollingSample& sample, LoadRule rule, double normal_load_n,
                       const RollingBodyMass& body)
{
  RulingLoad load = ruling_resultant(sample, rule, normal_load_n, body);
  if (load.uniform)
    return load;
  if (!(load.centre > 0 && load.centre < 1) || !(load.normal_n > 0))
  {
    load.normal_n = 0;
    return load;
  }
  load.from = load.centre > 2.0 / 3 ? 1 - 3 * (1 - load.centre) : 0;
  load.to = load.centre < 1.0 / 3 ? 3 * load.centre : 1;
  return load;
}

double held_fraction(double f, double loaded_from, double loaded_to, double end_margin)
{
  const double lo = loaded_from + end_margin, hi = loaded_to - end_margin;
  return lo <= hi ? std::clamp(f, lo, hi) : 0.5 * (loaded_from + loaded_to);
}
} // namespace rollcheck::contact

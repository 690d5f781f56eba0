#include "contact/rounded_end_problem.h"
#include <algorithm>

namespace rollcheck::contact
{
double effective_modulus(const RoundedEndSettings& s)
{
  return effective_modulus(s.youngs_modulus_pa, s.poisson_ratio, s.steel_counter_face);
}

double reference_radius(const RoundedEndSettings& s, const RoundedEndProblem& end)
{
  return std::max(end.sheet_radius(0), s.edge_radius_m);
}

LineHertz end_line_hertz(const RoundedEndSettings& s, const RoundedEndProblem& end)
{
  return line_contact(end.load.at_end_n_per_m, reference_radius(s, end), effective_modulus(s), s.poisson_ratio);
}
} // namespace rollcheck::contact

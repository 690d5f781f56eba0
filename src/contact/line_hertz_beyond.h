#pragma once
// A line load along a ruling prescribed as line Hertz pressure on the
// columns of a half-space grid from a column on (the rest of a loaded ruling
// beyond the window a contact is solved on), and the deflection it causes
// over the grid (contact/half_space_contact.h). Column i at x'_i carries
//   p_ij = p0 sqrt(1 - (y_j / b)^2) (|y_j| < b),  then scaled so that sum_j p_ij dy = q(x'_i)
// with p0 and b line Hertz's at q(x'_i) and the sheet's R(x'_i) (contact/hertz.h:
// K. L. Johnson, Contact Mechanics, CUP 1985, ch. 4), so that each column
// carries q exactly whatever its cells resolve of b.
#include "contact/half_space_contact.h"
#include "contact/ruling_line_load.h"
#include <cstddef>
#include <functional>
#include <vector>

namespace rollcheck::contact
{
struct LineHertzBeyond
{
  HalfSpaceGrid grid;
  std::size_t first_column = 0; ///< the first column loaded
  HalfSpaceDeflection influence;
  std::function<double(double)> sheet_radius; ///< R(x')
  double effective_modulus_pa = 0, poisson_ratio = 0;

  /// u (m) over the grid from `load` on the columns from first_column on.
  std::vector<double> deflection(const RulingLineLoad& load) const;
};
} // namespace rollcheck::contact

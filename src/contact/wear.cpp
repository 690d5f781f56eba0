#include "contact/wear.h"

namespace rollcheck::contact
{
double archard_depth(double p, double v, const WearParameters& w)
{
  // In the reference's order of operations.
  return w.archard_coefficient * p * v * w.contact_time_s / w.hardness_pa;
}
} // namespace rollcheck::contact

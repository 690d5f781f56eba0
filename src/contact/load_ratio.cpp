#include "contact/load_ratio.h"

namespace rollcheck::contact
{
double load_ratio(double load_n_per_m, double radius_m, double effective_modulus_pa)
{
  return load_n_per_m / (effective_modulus_pa * radius_m);
}
} // namespace rollcheck::contact

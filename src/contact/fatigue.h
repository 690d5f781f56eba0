#pragma once
// Fatigue damage of one stress cycle: Basquin's S-N law with an endurance
// limit, and Miner's linear damage rule (the preprint's FDS section):
//   N_f(sigma_a) = (sigma_a / sigma_f')^(1 / b)   for sigma_a >= sigma_e,
//   N_f = infinity                                below sigma_e (or sigma_a <= 0),
//   damage of one cycle d = 1 / N_f, summed over cycles (failure at D = 1).
#include "contact/contact_parameters.h"

namespace rollcheck::contact
{
double cycles_to_failure(double stress_amplitude_pa, const FatigueParameters& fatigue);
double miner_damage_per_cycle(double stress_amplitude_pa, const FatigueParameters& fatigue);
} // namespace rollcheck::contact

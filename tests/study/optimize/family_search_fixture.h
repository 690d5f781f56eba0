#pragma once
// The cheapest family search the optimiser's tests share: the approximate
// oracle's CDS at 100 points per circle, milliseconds per genome.
#include "study/optimize/optimize_family.h"

inline rollcheck::study::optimize::FamilySearchSettings cheap_family_search()
{
  rollcheck::study::optimize::FamilySearchSettings s;
  s.points = 100;
  s.max_evaluations = 15;
  s.sweep_points = 3;
  s.threads = 2;
  return s;
}

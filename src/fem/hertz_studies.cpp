#include "fem/hertz_studies.h"

namespace rollcheck::fem
{
std::vector<HertzSetup> convergence_study(const HertzSetup& base, const std::vector<Model>& models)
{
  std::vector<HertzSetup> setups;
  for (Model model : models)
    for (int degree : {1, 2})
    {
      const bool solid = model == Model::solid;
      const int finest = solid ? (degree == 1 ? 2 : 0) : (degree == 1 ? 6 : 4);
      for (int refine = 0; refine <= finest; ++refine)
      {
        HertzSetup s = base;
        s.model = model;
        s.degree = degree;
        s.refine = refine;
        s.contact_element_size_m = 0;
        s.xdmf_path.clear();
        setups.push_back(s);
      }
    }
  return setups;
}

std::vector<HertzSetup> penalty_study(const HertzSetup& base, const std::vector<Model>& models)
{
  std::vector<HertzSetup> setups;
  for (Model model : models)
    for (double c : {0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0})
    {
      HertzSetup s = base;
      s.model = model;
      s.degree = 1;
      s.refine = -1;
      s.contact_element_size_m = 0;
      s.penalty_c = c;
      s.xdmf_path.clear();
      setups.push_back(s);
    }
  return setups;
}
} // namespace rollcheck::fem

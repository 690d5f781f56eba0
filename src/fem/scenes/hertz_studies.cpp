#include "fem/scenes/hertz_studies.h"
#include "core/error.h"
#include "fem/scenes/hertz_json.h"
#include <algorithm>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
namespace
{
int resolved_refine(const HertzSettings& s) { return s.refine >= 0 ? s.refine : default_refine(s.model, s.degree); }

/// The base setup (body, load, solver options) with a study's model, degree
/// and mesh level, writing no fields; the contact's refinement, cap and
/// recovery as the base gives them, where it leaves them to the model: none,
/// unstructured, lumped (the studies' rows name what they change).
HertzSettings study_setup(const HertzSettings& base, Model model, int degree, int refine)
{
  HertzSettings s = base;
  s.model = model;
  s.degree = degree;
  s.refine = refine;
  for (int* levels : {&s.pole_refine, &s.edge_refine})
    *levels = std::max(*levels, 0);
  if (s.contact_cap == ContactCapMesh::automatic)
    s.contact_cap = ContactCapMesh::unstructured;
  if (s.pressure_recovery == PressureRecovery::automatic)
    s.pressure_recovery = PressureRecovery::lumped;
  s.contact_element_size_m = 0;
  s.xdmf_path.clear();
  return s;
}
} // namespace

std::vector<HertzSettings> convergence_study(const HertzSettings& base, const std::vector<Model>& models)
{
  std::vector<HertzSettings> setups;
  for (Model model : models)
    for (int degree : {1, 2})
    {
      const bool solid = model == Model::solid;
      const int finest = solid ? (degree == 1 ? 2 : 0) : (degree == 1 ? 6 : 4);
      for (int refine = 0; refine <= finest; ++refine)
        setups.push_back(study_setup(base, model, degree, refine));
    }
  return setups;
}

std::vector<HertzSettings> pointwise_study(const HertzSettings& base)
{
  using Recoveries = std::vector<PressureRecovery>;
  const Recoveries both = {PressureRecovery::lumped, PressureRecovery::consistent};
  std::vector<HertzSettings> setups;
  const auto add = [&](Model model, int degree, int refine, double penalty_c, const Recoveries& recoveries,
                       int pole_refine = 0, int edge_refine = 0, ContactCapMesh cap = ContactCapMesh::unstructured) {
    for (PressureRecovery recovery : recoveries)
    {
      HertzSettings s = study_setup(base, model, degree, refine);
      s.pressure_recovery = recovery;
      s.penalty_c = penalty_c;
      s.pole_refine = pole_refine;
      s.edge_refine = edge_refine;
      s.contact_cap = cap;
      setups.push_back(s);
    }
  };
  add(Model::axisymmetric, 1, -1, base.penalty_c, both);
  for (int refine = 0; refine <= 3; ++refine)
    add(Model::solid, 1, refine, base.penalty_c, both);
  add(Model::solid, 1, -1, 10 * base.penalty_c, both);
  // P2: the penalty's own nodal pressure too (with the 3D P1 vertex rule it
  // is the lumped one, tests/fem/test_hertz_pressure_recovery.cpp).
  add(Model::solid, 2, 0, base.penalty_c, {PressureRecovery::lumped, PressureRecovery::consistent,
                                            PressureRecovery::penalty});
  // The contact's pole and edge refined (the consistent recovery is worse
  // on every mesh above), the edge also at 10x c; the touching recovery
  // where the edge is refined.
  add(Model::solid, 2, 0, base.penalty_c, {PressureRecovery::lumped}, 2, 0);
  add(Model::solid, 2, 0, base.penalty_c, {PressureRecovery::lumped, PressureRecovery::touching}, 2, 2);
  add(Model::solid, 2, 0, base.penalty_c, {PressureRecovery::lumped}, 2, 3);
  add(Model::solid, 2, 0, base.penalty_c, {PressureRecovery::touching}, 3, 3);
  add(Model::solid, 2, 0, 10 * base.penalty_c, {PressureRecovery::lumped}, 2, 2);
  // The cap's node rings (the 3D default, with_model_defaults) against
  // gmsh's cap at the same sizes, both recoveries.
  add(Model::solid, 2, 0, base.penalty_c, {PressureRecovery::lumped, PressureRecovery::touching}, 2, 2,
      ContactCapMesh::rings);
  return setups;
}

std::vector<HertzSettings> penalty_study(const HertzSettings& base, const std::vector<Model>& models)
{
  std::vector<HertzSettings> setups;
  for (Model model : models)
    for (double c : {0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0})
    {
      HertzSettings s = study_setup(base, model, 1, -1);
      s.penalty_c = c;
      setups.push_back(s);
    }
  return setups;
}

HertzStudy run_study(MPI_Comm comm, const std::string& name, const std::vector<HertzSettings>& setups)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  HertzStudy study{name, {}};
  for (std::size_t i = 0; i < setups.size(); ++i)
  {
    const HertzSettings& s = setups[i];
    if (rank == 0)
      spdlog::info("study {} [{}/{}]: {} P{} refine {} c {}", name, i + 1, setups.size(), model_name(s.model),
                   s.degree, resolved_refine(s), s.penalty_c);
    HertzStudyRun run{s, std::nullopt, ""};
    try
    {
      run.result = solve_hertz(comm, s);
    }
    catch (const ComputationError& e)
    {
      run.failure = e.what();
    }
    study.runs.push_back(std::move(run));
  }
  return study;
}

std::string to_csv(const HertzStudy& study)
{
  std::string csv = "model,degree,refine,pole_refine,edge_refine,contact_cap,penalty_c,pressure_recovery,elements_across_contact,dofs,cells,ranks,newton_its,krylov_its,"
                    "wall_s,solve_s,size_error,p0_error,p_max_nodal_error,max_shear_error,max_shear_depth_error,"
                    "max_von_mises_error,max_von_mises_depth_error,force_error,profile_rms_error,"
                    "profile_rms_error_interior,penalty_error_estimate,discretisation_error_estimate,flags,status\n";
  for (const HertzStudyRun& run : study.runs)
  {
    const HertzSettings& s = run.setup;
    csv += fmt::format("{},{},{},{},{},{},{},{},", model_name(s.model), s.degree, resolved_refine(s), s.pole_refine,
                       s.edge_refine, contact_cap_name(s.contact_cap), s.penalty_c, recovery_name(s.pressure_recovery));
    if (!run.result)
    {
      std::string message = run.failure;
      std::replace(message.begin(), message.end(), ',', ';');
      csv += std::string(21, ',') + "failed: " + message + "\n";
      continue;
    }
    const HertzResult& r = *run.result;
    const double length = s.model == Model::plane_strain ? s.length_m : 1.0;
    const HertzReference& h = r.hertz;
    csv += fmt::format(
        "{:.6g},{},{},{},{},{},{:.6g},{:.6g},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
        "{:.6e},{:.6e},{:.6e},{:.6e},{},ok\n",
        r.elements_across_contact, r.dofs, r.cells, r.ranks, r.newton_iterations, r.krylov_iterations, r.wall_s,
        r.solve_s, relative_error(r.contact_size_m, h.contact_size_m),
        relative_error(r.peak_pressure_pa, h.peak_pressure_pa),
        relative_error(r.max_nodal_pressure_pa, h.peak_pressure_pa),
        relative_error(r.max_shear.value, h.max_shear_pa), relative_error(r.max_shear.depth_m, h.max_shear_depth_m),
        relative_error(r.max_von_mises.value, h.max_von_mises_pa),
        relative_error(r.max_von_mises.depth_m, h.max_von_mises_depth_m),
        relative_error(r.load_reaction * length, s.force_n), r.profile_rms_error, r.profile_rms_error_interior,
        r.penalty_error_estimate,
        r.discretisation_error_estimate, fmt::join(r.flags, " "));
  }
  return csv;
}

nlohmann::json to_json(const HertzStudy& study)
{
  nlohmann::json runs = nlohmann::json::array();
  for (const HertzStudyRun& run : study.runs)
  {
    const HertzSettings& s = run.setup;
    runs.push_back(run.result ? to_json(*run.result)
                              : nlohmann::json{{"model", model_name(s.model)},
                                               {"degree", s.degree},
                                               {"refine", resolved_refine(s)},
                                               {"pole_refine", s.pole_refine},
                                               {"edge_refine", s.edge_refine},
                                               {"contact_cap", contact_cap_name(s.contact_cap)},
                                               {"penalty_c", s.penalty_c},
                                               {"pressure_recovery", recovery_name(s.pressure_recovery)},
                                               {"failed", run.failure}});
  }
  return {{"study", study.name}, {"runs", runs}};
}
} // namespace rollcheck::fem

#pragma once
// The compiled UFL forms of forms/hertz.py for one model and degree. Only
// this file's .cpp includes the generated header.
#include "fem/mesh/mesh_grading.h"
#include "fem/model.h"
#include <string>
#include <ufcx.h>

namespace rollcheck::fem
{
struct ContactForms
{
  using SpaceFactory = ufcx_function_space* (*)(const char*);
  ufcx_form* residual;      ///< F(u; v): elastic minus penalty contact work
  ufcx_form* jacobian;      ///< dF/du
  ufcx_form* energy;        ///< elastic + penalty energy (line search)
  ufcx_form* contact_force; ///< integral of the contact pressure
  ufcx_form* pressure_load; ///< integral of p q (q: P1 test), for the nodal pressure
  ufcx_form* stress_load;   ///< integral of sigma : tau (tau: P1 3x3 test)
  ufcx_form* volume_mass;   ///< integral of q: lumped P1 volume mass
  ufcx_form* contact_mass;  ///< integral of q over the contact surface
  SpaceFactory displacement_space; ///< argument "v_0" of residual
  SpaceFactory scalar_p1_space;    ///< argument "v_0" of volume_mass
  SpaceFactory tensor_p1_space;    ///< argument "v_0" of stress_load
  SpaceFactory vector_p1_space;    ///< argument "v_0" of the P1 residual (field output)
  /// Names in the forms end with this: "axi_p1", "solid_p2", ...
  std::string suffix;
};

ContactForms contact_forms(Model model, int degree);
} // namespace rollcheck::fem

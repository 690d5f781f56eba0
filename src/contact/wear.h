#pragma once
// Archard's wear law in its local form (the preprint's WDS section): sliding a
// distance v dt under contact pressure p removes a depth
//   dh = k p v dt / H
// (k dimensionless wear coefficient, H hardness). The reference code sums dh
// as a "wear volume" and dh / a_f (a_f the face area) as a "wear depth"
// (paper-compat switch wear_depth_per_face_area); corrected, dh is the depth
// and dh pi a^2 (a the Hertz contact radius) the volume.
#include "contact/contact_parameters.h"

namespace rollcheck::contact
{
double archard_depth(double pressure_pa, double sliding_speed_m_s, const WearParameters& wear);
} // namespace rollcheck::contact

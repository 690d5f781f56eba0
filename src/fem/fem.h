#pragma once
// Layer: fem. Owns the elastic contact of a body against a rigid plane, or
// against a second elastic body by node pairs, solved by the finite element
// method on DOLFINx 0.5.2 with a penalty: the UFL forms (forms/hertz.py), the
// gmsh scene meshes graded towards the contact (quarter disc for the
// axisymmetric and plane-strain models, quarter hemisphere in 3D, the 3D slab
// of a contact ruling, the plane-strain crease, the 3D end of a ruling at a
// rim, alone or on a block), the plane-strain slices and the 3D slab of a
// line contact, the crease and rim-end studies, line Hertz between two bodies,
// the load-controlled Newton/Krylov solves with checked convergence (a
// refined level started from the coarser one's solution), and
// the post-processing that sets every result next to Hertz theory
// (contact/hertz.h). Knows nothing of files beyond its own XDMF field output,
// nor of the command line.
#include "fem/crease_contact.h"
#include "fem/line_block_contact.h"
#include "fem/rim_end_contact.h"
#include "fem/hertz_setup.h"
#include "fem/hertz_solve.h"
#include "fem/hertz_studies.h"
#include "fem/petsc_session.h"
#include "fem/slab_contact.h"
#include "fem/slice_contact.h"

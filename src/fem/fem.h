#pragma once
// Layer: fem, the engine. Owns elastic contact solved by the finite element
// method on DOLFINx 0.5.2 with a penalty, independent of any one scene: the
// model's coordinates (model.h), the penalty-contact problem against a rigid
// plane or a second body by node pairs (penalty_contact.h; node_pairs.h,
// mortar_pairs.h, clip_to_triangle.h), its solver defaults (solver_defaults.h)
// and the lumped projection it shares with the fields, load control,
// nodal fields and contact measures, interpolation between meshes, the PETSc
// session and the field output. Beside it, fem/mesh builds one gmsh mesh per
// scene (graded towards the contact) and fem/scenes holds the scenes solved
// on this engine (Hertz, slices, slab, crease, rim end, line block, sections,
// whole body). Data flows mesh -> engine -> scenes; the engine includes no
// scene. Knows nothing of files beyond its field output, nor of the command
// line.
#include "fem/all_gather.h"
#include "fem/clip_to_triangle.h"
#include "fem/contact_forms.h"
#include "fem/contact_measures.h"
#include "fem/interpolate_between_meshes.h"
#include "fem/load_control.h"
#include "fem/lumped_projection.h"
#include "fem/model.h"
#include "fem/mortar_pairs.h"
#include "fem/nodal_fields.h"
#include "fem/node_pair.h"
#include "fem/node_pairs.h"
#include "fem/on_rank_zero.h"
#include "fem/penalty_contact.h"
#include "fem/petsc_session.h"
#include "fem/share_out.h"
#include "fem/solver_defaults.h"
#include "fem/write_fields.h"

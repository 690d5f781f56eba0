#pragma once
// The contact scenes solved on the fem engine (fem.h): Hertz (axisymmetric,
// plane strain, 3D), the plane-strain slices and the 3D slab of a ruling,
// the crease, the rim end alone or on a block, line Hertz between two
// bodies, the sections and the whole body. One header per scene.
#include "fem/scenes/crease_contact.h"
#include "fem/scenes/line_block_contact.h"
#include "fem/scenes/rim_end_contact.h"
#include "fem/scenes/hertz_solve.h"
#include "fem/scenes/hertz_studies.h"
#include "fem/scenes/slab_contact.h"
#include "fem/scenes/slice_contact.h"

#pragma once
// Wing of the study layer: the rims over the loop: the loop's ends found by an
// end's interior angle (flattest_loop_ends.h), the nearly flat rounded end by
// half-space theory at those ends (flat_rim_contact.h) and the end-aware loop
// scores from the FEM end table (rim_loop.h).
#include "study/rims/flat_rim_contact.h"
#include "study/rims/flattest_loop_ends.h"
#include "study/rims/rim_loop.h"

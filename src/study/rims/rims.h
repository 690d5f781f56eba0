#pragma once
// Wing of the study layer: the rims over the loop: the loop's ends found by an
// end's interior angle (flattest_loop_ends.h), the nearly flat rounded end by
// half-space theory at those ends (flat_rim_contact.h) and the end-aware loop
// scores from the FEM end table and the flat-rim table (rim_loop.h), and the
// reports and JSON of one end and of the loop (rim_report.h, rim_end_json.h).
#include "study/rims/end_ratios.h"
#include "study/rims/end_table.h"
#include "study/rims/flat_rim_contact.h"
#include "study/rims/flat_rim_table.h"
#include "study/rims/flattest_loop_ends.h"
#include "study/rims/oblique_end.h"
#include "study/rims/rim_end_json.h"
#include "study/rims/rim_loop.h"
#include "study/rims/rim_report.h"
#include "study/rims/table_nodes.h"

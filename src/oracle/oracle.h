#pragma once
// Layer: oracle. Owns rolling kinematics and contact detection: the preprint's
// approximate oracle (Algorithm 1, a prescribed rotation sequence) and its
// rigid-body oracle (Algorithm 2, Euler's equations with a quaternion update),
// both producing a Trajectory (per sample: orientation, angular velocity where
// there is one, support vertex, contacting faces); the score template shared by
// every distribution score (area-weighted variance of a per-face accumulator
// against the area fractions) and the contact distribution score CDS built on
// it; the paper-compatibility switches that reproduce the reference code's
// quirks; and the parametric search over the two-circle roller family.
// Knows nothing of materials or stresses: those are evaluated on a trajectory
// by the contact layer.
#include "oracle/approximate_oracle.h"
#include "oracle/contact_distribution.h"
#include "oracle/distribution_score.h"
#include "oracle/paper_compat.h"
#include "oracle/parametric_search.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include "oracle/trajectory.h"

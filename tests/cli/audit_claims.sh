#!/usr/bin/env bash
# The default suite's audit test: audit_quick.sh on the claims whose commands
# are oracle and mesh runs on the reference meshes and the preprint's
# rollers (a few seconds each; the whole table, with its FEM, rim, robustness
# and search commands, is audit_quick.sh, label long). They include the Hertz
# table, whose commands are the reference meshes' paper-compatible runs, and
# a claim that cannot be tested (geometry_only_sds).
#   audit_claims.sh ROLLCHECK SOURCE_DIR TMP_DIR
AUDIT_CLAIMS=oloid_area,hertz_table,pressure_uniformity,discrete_gaussian,geometry_only_sds,mean_curvature_spread,tds_lowest,fatigue_values \
  exec bash "$(dirname "$0")/audit_quick.sh" "$@"

#pragma once
// The record's schema of the scenes' JSON summaries as the results store
// keeps them (io/results_store.h): the SI unit of every field that has one,
// the column names of the fields that are tables (rows of numbers), and the
// fields that are lists of strings (an empty list holds no type of its own).
//
// A field is named by its key as the scene records it; the same key means the
// same quantity in every scene (docs/guide/command-line.md#conventions). The
// unit is declared here with the field, once, not read off the key's
// spelling: a key whose unit is not declared is a pure number or a count
// ("1"). A new field with a unit is added to the table in result_fields.cpp;
// tests/cli/results_store_units.sh checks a batch's store against it.
#include <string>
#include <string_view>
#include <vector>

namespace rollcheck::io {
/// What the store records of a summary field besides its value.
struct ResultField {
  std::string
      unit; ///< SI unit ("m/s", "1/m^2", "Pa"), "1" for a pure number or a
            ///< count; for a table one unit per column, joined by ", "
  std::vector<std::string>
      columns;            ///< a table's column names; empty for any other field
  bool text_list = false; ///< a list of strings (hertz's flags): stored as
                          ///< strings even when empty
};

/// The field `key` of the summary group `group` (its parent group's name:
/// "convergence" for convergence/cds).
ResultField result_field(std::string_view group, std::string_view key);
} // namespace rollcheck::io

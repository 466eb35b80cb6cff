#pragma once
// User data types (ARRAY, STRUCT, enumerations, aliases) are modelled element by element: the
// semantics and the engines only know Boolean, integer, TIME and FB-instance variables, so the
// readers' aggregates are lowered to those once, right after reading (docs/semantics.md 1.7a).

#include "model/chart.hpp"
#include "model/diagnostic.hpp"

namespace sfcv::model {

/// Replaces, in every POU of `project`:
/// - a variable of an ARRAY, STRUCT or alias type by its elements, named by their paths
///   (`a[2]`, `s.x`, `m[1,2].y`), and a variable of an enumeration by an integer variable whose
///   range spans the enumerators' values;
/// - an element chosen by a non-constant index by a MUX over the elements (an index out of
///   bounds is a range error, as for MUX), an assignment to one by a CASE over them;
/// - an enumerator (`Red`, `Color#Red`, `Color.Red`), also as a CASE label, by its value.
/// Errors (unknown types, recursive types, bounds, too many elements) go to `diags` with their
/// locations; the project is then not to be used.
void lower_data_types(Project& project, Diagnostics& diags);

}  // namespace sfcv::model

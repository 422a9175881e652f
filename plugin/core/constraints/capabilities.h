// What works with what: each contact kind against the dimension, friction, the sensitivity
// analysis, MPI, the file-driven front end and fetiContactStart. Each kind declares its own
// row in its unit (constraints/contact/<kind>.h); the table is the registry's rows in order
// (constraints/contact/registry.cpp). Every refusal of an unsupported combination asks this
// table and words its message one way; docs/reference.md prints it (ffeti-solve
// --capabilities), and its gaps are the roadmap.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ffeti {

/// A contact kind is its position in the registry (contact_discretizations(), the order of
/// its rows in B). The kinds other code names have a name here; a kind added later needs
/// none: its unit is known by its position.
enum class ContactKind : std::uint8_t { node_to_segment, obstacle, ball, mortar, node_to_face, node_to_node };

/// What a problem may ask of its contact kind. `rows`: the kind's rows at all (in a plane
/// problem or in three dimensions).
enum class Feature : std::uint8_t { rows, friction, sensitivity, sensitivity_with_friction, mpi, ffeti_solve, contact_start };

/// In which dimensions something works.
struct Dimensions {
  bool plane = false, solid = false;
};
inline constexpr Dimensions kNowhere{false, false}, kPlaneOnly{true, false}, kSolidOnly{false, true}, kBothDimensions{true, true};

/// A kind's row: `kind` is set by the registry (its position).
struct KindCapabilities {
  ContactKind kind;
  const char* name;       ///< in messages and the table: "node-to-segment"
  const char* selected_by;  ///< the fetiSetup arguments that ask for it
  Dimensions rows, friction, sensitivity, sensitivity_with_friction, mpi, ffeti_solve, contact_start;
};

/// The table, one entry per registered kind in the registry's order.
const std::vector<KindCapabilities>& capability_table();

/// Whether `kind` supports `feature` in `dimension` (2 or 3).
bool supports(ContactKind kind, Feature feature, int dimension);

/// The one wording of a refusal, after "argument: ": "<kind> contact does not support
/// <feature> yet (see the capability table in docs/reference.md)".
std::string unsupported(ContactKind kind, Feature feature, int dimension);

/// InputError "<argument>: " + unsupported(...) unless `kind` supports `feature` in `dimension`.
void require(ContactKind kind, Feature feature, int dimension, const std::string& argument);

/// The table as markdown, as docs/reference.md holds it between <!-- capabilities begin/end -->.
std::string capability_table_markdown();

}  // namespace ffeti

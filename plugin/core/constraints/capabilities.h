// What works with what: each contact kind against the dimension, friction, the sensitivity
// analysis, MPI, the file-driven front end and fetiContactStart, declared once here. Every
// refusal of an unsupported combination asks this table and words its message one way;
// docs/reference.md prints it (ffeti-solve --capabilities), and its gaps are the roadmap.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ffeti {

enum class ContactKind : std::uint8_t { node_to_node, node_to_segment, obstacle, ball, node_to_face, mortar };

/// What a problem may ask of its contact kind. `rows`: the kind's rows at all (in a plane
/// problem or in three dimensions).
enum class Feature : std::uint8_t { rows, friction, sensitivity, sensitivity_with_friction, mpi, ffeti_solve, contact_start };

/// In which dimensions something works.
struct Dimensions {
  bool plane = false, solid = false;
};

struct KindCapabilities {
  ContactKind kind;
  const char* name;       ///< in messages and the table: "node-to-segment"
  const char* selected_by;  ///< the fetiSetup arguments that ask for it
  Dimensions rows, friction, sensitivity, sensitivity_with_friction, mpi, ffeti_solve, contact_start;
};

/// The table, one entry per kind in ContactKind's order.
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

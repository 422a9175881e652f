#include "constraints/capabilities.h"

#include "constraints/contact/contact_discretization.h"

#include "base/errors.h"

#include <sstream>

namespace ffeti {
namespace {

Dimensions cell(const KindCapabilities& k, Feature feature) {
  switch (feature) {
    case Feature::rows: return k.rows;
    case Feature::friction: return k.friction;
    case Feature::sensitivity: return k.sensitivity;
    case Feature::sensitivity_with_friction: return k.sensitivity_with_friction;
    case Feature::mpi: return k.mpi;
    case Feature::ffeti_solve: return k.ffeti_solve;
    case Feature::contact_start: return k.contact_start;
  }
  return kNowhere;
}

const char* feature_name(Feature feature) {
  switch (feature) {
    case Feature::rows: return "rows";
    case Feature::friction: return "friction";
    case Feature::sensitivity: return "sensitivity";
    case Feature::sensitivity_with_friction: return "sensitivity with friction";
    case Feature::mpi: return "MPI";
    case Feature::ffeti_solve: return "ffeti-solve";
    case Feature::contact_start: return "fetiContactStart";
  }
  return "";
}

const char* dimension_name(int dimension) { return dimension == 3 ? "three dimensions" : "plane problems"; }

}  // namespace

const std::vector<KindCapabilities>& capability_table() {
  static const std::vector<KindCapabilities> table = [] {
    std::vector<KindCapabilities> rows;
    for (const auto& unit : contact_discretizations()) {
      rows.push_back(unit->capabilities());
      rows.back().kind = static_cast<ContactKind>(rows.size() - 1);
    }
    return rows;
  }();
  return table;
}

bool supports(ContactKind kind, Feature feature, int dimension) {
  const Dimensions d = cell(capability_table()[static_cast<size_t>(kind)], feature);
  return dimension == 3 ? d.solid : d.plane;
}

std::string unsupported(ContactKind kind, Feature feature, int dimension) {
  const KindCapabilities& k = capability_table()[static_cast<size_t>(kind)];
  const Dimensions d = cell(k, feature);
  // Named with the dimension where the feature works in the other one (or for the rows
  // themselves), plainly where it works in neither.
  std::string what = feature == Feature::rows ? dimension_name(dimension) : feature_name(feature);
  if (feature != Feature::rows && (d.plane || d.solid)) what += std::string(" in ") + dimension_name(dimension);
  return std::string(k.name) + " contact does not support " + what +
         " yet (see the capability table in docs/reference.md)";
}

void require(ContactKind kind, Feature feature, int dimension, const std::string& argument) {
  if (!supports(kind, feature, dimension)) throw InputError(argument + ": " + unsupported(kind, feature, dimension));
}

std::string capability_table_markdown() {
  const Feature features[] = {Feature::friction, Feature::sensitivity, Feature::sensitivity_with_friction,
                              Feature::mpi,      Feature::ffeti_solve, Feature::contact_start};
  std::ostringstream out;
  out << "| contact | selected by | plane (2D) | solid (3D)";
  for (Feature f : features) out << " | " << feature_name(f);
  out << " |\n|---|---|---|---";
  for (size_t i = 0; i < std::size(features); ++i) out << "|---";
  out << "|\n";
  for (const KindCapabilities& k : capability_table()) {
    out << "| " << k.name << " | `" << k.selected_by << "` | " << (k.rows.plane ? "yes" : "—") << " | "
        << (k.rows.solid ? "yes" : "—");
    for (Feature f : features) {
      const Dimensions d = cell(k, f);
      // "yes" where the feature works wherever the kind does; the dimension where it works in one only.
      const bool everywhere = (d.plane || !k.rows.plane) && (d.solid || !k.rows.solid) && (d.plane || d.solid);
      out << " | " << (everywhere ? "yes" : d.plane ? "plane only" : d.solid ? "3D only" : "—");
    }
    out << " |\n";
  }
  return out.str();
}

}  // namespace ffeti

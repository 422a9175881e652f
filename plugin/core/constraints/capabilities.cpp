#include "constraints/capabilities.h"

#include "base/errors.h"

#include <sstream>

namespace ffeti {
namespace {

constexpr Dimensions kNone{false, false}, kPlane{true, false}, kSolid{false, true}, kBoth{true, true};

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
  return kNone;
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
  // kind, name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI,
  // ffeti-solve, fetiContactStart
  static const std::vector<KindCapabilities> table = {
      {ContactKind::node_to_node, "node-to-node", "contactSlave, contactMaster", kBoth, kBoth, kBoth, kNone, kBoth,
       kPlane, kPlane},
      {ContactKind::node_to_segment, "node-to-segment", "contactSlave, contactSegments", kPlane, kPlane, kPlane, kNone,
       kPlane, kPlane, kPlane},
      {ContactKind::obstacle, "obstacle", "contactSlave, obstacle", kBoth, kBoth, kBoth, kNone, kBoth, kBoth, kPlane},
      {ContactKind::ball, "ball", "contactSlave, obstacleBall", kBoth, kBoth, kBoth, kNone, kBoth, kNone, kPlane},
      {ContactKind::node_to_face, "node-to-face", "contactSlave, contactFaces", kSolid, kSolid, kSolid, kNone, kSolid,
       kSolid, kNone},
      {ContactKind::mortar, "mortar", "contactSlaveFaces, contactFaces", kSolid, kSolid, kSolid, kNone, kSolid,
       kNone, kNone},
  };
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

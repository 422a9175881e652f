#include "constraints/constraints.h"

#include "constraints/constraint_rows.h"
#include "constraints/contact/contact_discretization.h"

#include "base/errors.h"

#include <algorithm>

namespace ffeti {

int Constraints::count(RowKind k) const {
  return static_cast<int>(std::count(kind.begin(), kind.end(), k));
}

Constraints build_constraints(std::vector<DofRecord> records, const std::vector<SegmentRecord>& segments,
                              const std::vector<FaceRecord>& faces, const ContactInput& contact, FetiVariant variant,
                              double snap) {
  sort_by_subdomain_and_dof(records);
  const ContactRecords in{records, segments, faces, contact, snap};
  const int dimension = contact.three_d ? 3 : 2;
  std::vector<const ContactDiscretization*> selected;
  const ContactDiscretization* searched = nullptr;
  for (const auto& unit : contact_discretizations()) {
    if (!unit->selected(in)) continue;
    if (contact.has_friction())
      require(unit->kind(), Feature::friction, dimension, contact.friction >= 0 ? "friction" : "slipBound");
    selected.push_back(unit.get());
    if (unit->searched_argument()) searched = unit.get();
  }
  std::vector<Row> rows;
  add_gluing_rows(records, snap, rows);
  if (variant == FetiVariant::tfeti) add_dirichlet_rows(records, rows);
  for (const ContactDiscretization* unit : selected) unit->add_rows(in, rows);
  Constraints result;
  // Rows of slaves beyond the radius leave before the Dirichlet substitution: they are
  // evaluated on the whole u, prescribed values included.
  const auto watched = std::stable_partition(rows.begin(), rows.end(), [](const Row& r) { return !r.beyond_reach; });
  for (auto row = watched; row != rows.end(); ++row) {
    auto& out = result.beyond_reach;
    out.entries.insert(out.entries.end(), row->entries.begin(), row->entries.end());
    out.row_start.push_back(static_cast<int>(out.entries.size()));
    out.rhs.push_back(row->rhs);
  }
  rows.erase(watched, rows.end());
  // A slave far from every master gets no row (no contact possible there); none at all
  // means the contact asked for cannot happen: most likely a radius or a surface mislaid.
  const bool has_slaves = std::any_of(records.begin(), records.end(), [](const DofRecord& r) { return r.slave; });
  if (searched && has_slaves &&
      std::none_of(rows.begin(), rows.end(), [](const Row& r) { return r.kind == RowKind::contact; }))
    throw InputError(std::string(searched->searched_argument()) + ": no slave node has a master " +
                     searched->master_word() + " of another body within contactRadius = " +
                     std::to_string(contact.search_distance) +
                     " (no contact row at all): check the radius, which surfaces are slave and master, and that "
                     "each face is ordered with (b - a) x (c - a) out of its body (ffetiBoundaryFaces)");
  if (variant == FetiVariant::feti1) substitute_dirichlet(records, rows);

  std::stable_partition(rows.begin(), rows.end(), [](const Row& r) { return r.equality; });
  if (contact.has_friction()) add_friction_rows(records, rows);
  result.tangent_directions = contact.three_d ? 2 : 1;
  for (const ContactDiscretization* unit : selected) result.contact_kinds.push_back(unit->kind());
  for (const Row& row : rows) {
    result.entries.insert(result.entries.end(), row.entries.begin(), row.entries.end());
    result.row_start.push_back(static_cast<int>(result.entries.size()));
    result.rhs.push_back(row.rhs);
    result.kind.push_back(row.kind);
    result.equality_rows += row.equality ? 1 : 0;
    if (row.kind == RowKind::contact) result.geometry.push_back(row.geometry);
    if (row.kind == RowKind::friction) {
      result.normal_row.push_back(row.normal_row);
      (contact.slip_bound >= 0 ? result.slip_bound : result.coulomb_coefficient).push_back(row.law_value);
      ++result.friction_rows;
    }
  }
  return result;
}

Constraints build_constraints(const std::vector<SubdomainInput>& subdomains,
                              const ContactInput& contact, FetiVariant variant) {
  std::vector<BoundingBox> boxes;
  std::vector<int> bodies, ids;
  for (const auto& sub : subdomains) {
    boxes.push_back(bounding_box(sub));
    bodies.push_back(sub.body);
    ids.push_back(static_cast<int>(ids.size()));
  }
  const double snap = snapping_length(boxes);
  ContactInput with_dimension = contact;
  with_dimension.three_d = !subdomains.empty() && !subdomains.front().z.empty();
  return build_constraints(constraint_candidates(subdomains, ids, contact, boxes, bodies, snap),
                           segment_records(subdomains, ids, contact), face_records(subdomains, ids, contact),
                           with_dimension, variant, snap);
}

std::vector<LocalConstraints> split_by_subdomain(const Constraints& constraints,
                                                 const std::vector<Eigen::Index>& sizes,
                                                 const std::vector<int>& global_ids) {
  std::vector<int> local_of;  // global subdomain -> local index (-1: not here)
  for (size_t k = 0; k < sizes.size(); ++k) {
    const int s = global_ids.empty() ? static_cast<int>(k) : global_ids[k];
    if (s >= static_cast<int>(local_of.size())) local_of.resize(static_cast<size_t>(s) + 1, -1);
    local_of[static_cast<size_t>(s)] = static_cast<int>(k);
  }
  std::vector<std::vector<Eigen::Triplet<double, int>>> triplets(sizes.size());
  std::vector<LocalConstraints> local(sizes.size());
  for (int row = 0; row < constraints.rows(); ++row)
    for (int k = constraints.row_start[static_cast<size_t>(row)];
         k < constraints.row_start[static_cast<size_t>(row) + 1]; ++k) {
      const ConstraintEntry& e = constraints.entries[static_cast<size_t>(k)];
      if (e.subdomain >= static_cast<int>(local_of.size()) || local_of[static_cast<size_t>(e.subdomain)] < 0) continue;
      const auto l = static_cast<size_t>(local_of[static_cast<size_t>(e.subdomain)]);
      LocalConstraints& block = local[l];
      if (block.rows.empty() || block.rows.back() != row) block.rows.push_back(row);
      triplets[l].emplace_back(static_cast<int>(block.rows.size()) - 1, e.dof, e.coefficient);
    }
  for (size_t s = 0; s < sizes.size(); ++s) {
    local[s].B.resize(static_cast<Eigen::Index>(local[s].rows.size()), sizes[s]);
    local[s].B.setFromTriplets(triplets[s].begin(), triplets[s].end());
    local[s].B.makeCompressed();
  }
  return local;
}

std::vector<int> touched_dofs(const SparseMatrix& B) {
  std::vector<int> dofs;
  for (int j = 0; j < B.outerSize(); ++j)
    if (B.outerIndexPtr()[j + 1] > B.outerIndexPtr()[j]) dofs.push_back(j);
  return dofs;
}

std::vector<std::vector<int>> rows_by_subdomain(const Constraints& constraints, int count) {
  std::vector<std::vector<int>> rows(static_cast<size_t>(count));
  for (int row = 0; row < constraints.rows(); ++row)
    for (int k = constraints.row_start[static_cast<size_t>(row)];
         k < constraints.row_start[static_cast<size_t>(row) + 1]; ++k) {
      auto& list = rows[static_cast<size_t>(constraints.entries[static_cast<size_t>(k)].subdomain)];
      if (list.empty() || list.back() != row) list.push_back(row);
    }
  return rows;
}

}  // namespace ffeti

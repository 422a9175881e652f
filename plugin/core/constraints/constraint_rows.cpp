#include "constraints/constraint_rows.h"

#include "base/errors.h"
#include "base/parallel_sort.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace ffeti {
namespace {

/// A record with its node snapped to a grid of the snapping length; the sort keys copied
/// beside the pointer, as sorting a million interface records through it missed the cache.
struct Located {
  const DofRecord* record;
  int body, component;
  long long ix, iy, iz;
  int subdomain, dof;
  auto key() const { return std::tie(body, component, ix, iy, iz); }
  auto position() const { return std::tie(component, ix, iy, iz); }
  auto order() const { return std::tie(body, component, ix, iy, iz, subdomain, dof); }
};

std::vector<Located> locate(const std::vector<DofRecord>& records, double snap,
                            bool (*select)(const DofRecord&)) {
  std::vector<Located> located;
  located.reserve(records.size());
  for (const DofRecord& r : records)
    if (select(r))
      located.push_back({&r, r.body, r.component, std::llround(r.x / snap), std::llround(r.y / snap),
                         std::llround(r.z / snap), r.subdomain, r.dof});
  parallel_stable_sort(located, [](const Located& a, const Located& b) { return a.order() < b.order(); });
  return located;
}

/// The slave dofs, one copy per physical dof: other copies are glued to it.
std::vector<Located> unique_slaves(const std::vector<DofRecord>& records, double snap) {
  std::vector<Located> slaves = locate(records, snap, [](const DofRecord& r) { return r.slave; });
  slaves.erase(std::unique(slaves.begin(), slaves.end(),
                           [](const Located& a, const Located& b) { return a.key() == b.key(); }),
               slaves.end());
  return slaves;
}

}  // namespace

void add_gluing_rows(const std::vector<DofRecord>& records, double snap, std::vector<Row>& rows) {
  const std::vector<Located> dofs = locate(records, snap, [](const DofRecord&) { return true; });
  std::vector<const DofRecord*> free_copies, fixed_copies;  // of one node's dof, reused
  for (size_t first = 0; first < dofs.size();) {
    size_t last = first + 1;
    while (last < dofs.size() && dofs[last].key() == dofs[first].key()) ++last;
    free_copies.clear(), fixed_copies.clear();
    for (size_t k = first; k < last; ++k) {
      const DofRecord& r = *dofs[k].record;
      if (k > first && r.subdomain == dofs[k - 1].record->subdomain) {
        if (r.dof == dofs[k - 1].record->dof) continue;  // the same dof, recorded twice
        throw InputError("X[" + std::to_string(r.subdomain) + "], Y[" + std::to_string(r.subdomain) +
                         "]: dofs " + std::to_string(dofs[k - 1].record->dof) + " and " +
                         std::to_string(r.dof) + " of one subdomain share a position and component");
      }
      (r.fixed ? fixed_copies : free_copies).push_back(&r);
    }
    // Chain the free copies and tie the chain to one fixed copy: with a Dirichlet row on
    // every fixed copy (Total FETI) or the fixed copies eliminated (FETI-1), B keeps full
    // row rank; a node with k free copies gets k-1 rows.
    if (!fixed_copies.empty() && !free_copies.empty()) free_copies.push_back(fixed_copies.front());
    for (size_t k = 1; k < free_copies.size(); ++k)
      rows.push_back({{{free_copies[k - 1]->subdomain, free_copies[k - 1]->dof, 1.0},
                       {free_copies[k]->subdomain, free_copies[k]->dof, -1.0}},
                      0.0, RowKind::gluing, true});
    first = last;
  }
}

void add_dirichlet_rows(const std::vector<DofRecord>& records, std::vector<Row>& rows) {
  for (const DofRecord& r : records)  // records are sorted by (subdomain, dof)
    if (r.fixed) rows.push_back({{{r.subdomain, r.dof, 1.0}}, r.value, RowKind::dirichlet, true});
}

std::vector<SlaveMaster> node_to_node_pairs(const std::vector<DofRecord>& records, double snap) {
  const std::vector<Located> slaves = unique_slaves(records, snap);
  std::vector<Located> masters = locate(records, snap, [](const DofRecord& r) { return r.master; });
  std::stable_sort(masters.begin(), masters.end(),
                   [](const Located& a, const Located& b) { return a.position() < b.position(); });
  const auto by_position = [](const Located& a, const Located& b) { return a.position() < b.position(); };
  std::vector<SlaveMaster> pairs;
  for (const Located& slave : slaves) {
    auto range = std::equal_range(masters.begin(), masters.end(), slave, by_position);
    auto master = std::find_if(range.first, range.second,
                               [&](const Located& m) { return m.record->body != slave.record->body; });
    if (master == range.second)
      throw InputError("contactSlave[" + std::to_string(slave.record->subdomain) + "]: dof " +
                       std::to_string(slave.record->dof) + " at (" + std::to_string(slave.record->x) +
                       ", " + std::to_string(slave.record->y) +
                       ") has no master dof of another body at the same position "
                       "(node-to-node contact needs matching meshes)");
    pairs.push_back({slave.record, master->record});
  }
  return pairs;
}

std::vector<SlaveNode> slave_nodes(const std::vector<DofRecord>& records, double snap, int components) {
  const std::vector<Located> slaves = unique_slaves(records, snap);  // sorted by key(): component 0 first
  std::vector<SlaveNode> nodes;
  const auto missing = [](const DofRecord& r, int c) {
    return InputError("contactSlave[" + std::to_string(r.subdomain) + "]: dof " + std::to_string(r.dof) +
                      " has no dof of component " + std::to_string(c) +
                      " at its node: list every component of each slave node for node-to-segment, node-to-face "
                      "or obstacle contact");
  };
  for (const Located& s : slaves) {
    if (s.record->component != 0) {
      // Its node's row is built from the component-0 dof: without one the node would get no
      // row at all, and the body then looked unrestrained.
      const auto wanted = std::make_tuple(s.record->body, 0, s.ix, s.iy, s.iz);
      const auto x_dof = std::lower_bound(slaves.begin(), slaves.end(), wanted,
                                          [](const Located& o, const auto& key) { return o.key() < key; });
      if (x_dof == slaves.end() || x_dof->key() != wanted) throw missing(*s.record, 0);
      continue;
    }
    std::array<const DofRecord*, 3> dofs{s.record, nullptr, nullptr};
    for (int c = 1; c < components; ++c) {
      const auto wanted = std::make_tuple(s.record->body, c, s.ix, s.iy, s.iz);  // the same node's other dofs
      const auto partner = std::lower_bound(slaves.begin(), slaves.end(), wanted,
                                            [](const Located& o, const auto& key) { return o.key() < key; });
      if (partner == slaves.end() || partner->key() != wanted) throw missing(*s.record, c);
      dofs[static_cast<size_t>(c)] = partner->record;
    }
    nodes.push_back({dofs[0], dofs[1], dofs[2]});
  }
  return nodes;
}

NodeComponents::NodeComponents(const std::vector<DofRecord>& records, double snap) : snap_(snap) {
  for (const DofRecord& r : records) sorted_.push_back({key(r, r.component), &r});
  std::sort(sorted_.begin(), sorted_.end());
}

NodeComponents::Key NodeComponents::key(const DofRecord& r, int component) const {
  return {r.subdomain, std::llround(r.x / snap_), std::llround(r.y / snap_), std::llround(r.z / snap_), component};
}

const DofRecord* NodeComponents::find(const DofRecord& at, int component) const {
  const Key wanted = key(at, component);
  const auto it = std::lower_bound(sorted_.begin(), sorted_.end(), wanted,
                                   [](const std::pair<Key, const DofRecord*>& e, const Key& k) { return e.first < k; });
  return it != sorted_.end() && it->first == wanted ? it->second : nullptr;
}

const DofRecord* fixed_record(const std::vector<DofRecord>& records, int subdomain, int dof) {
  auto it = std::lower_bound(records.begin(), records.end(), std::make_pair(subdomain, dof),
                             [](const DofRecord& r, const std::pair<int, int>& key) {
                               return std::make_pair(r.subdomain, r.dof) < key;
                             });
  return it != records.end() && it->subdomain == subdomain && it->dof == dof && it->fixed ? &*it : nullptr;
}

void substitute_dirichlet(const std::vector<DofRecord>& records, std::vector<Row>& rows) {
  std::vector<Row> kept;
  for (Row& row : rows) {
    std::vector<ConstraintEntry> free_entries;
    for (const ConstraintEntry& e : row.entries) {
      if (const DofRecord* fixed = fixed_record(records, e.subdomain, e.dof))
        row.rhs -= e.coefficient * fixed->value;
      else
        free_entries.push_back(e);
    }
    if (!free_entries.empty()) {
      row.entries = std::move(free_entries);
      kept.push_back(std::move(row));
    } else if ((row.equality && std::abs(row.rhs) > 1e-12) || (!row.equality && row.rhs < 0)) {
      throw InputError("dirichlet: the prescribed values violate a " +
                       std::string(row.kind == RowKind::contact ? "contact" : "gluing") +
                       " condition between fixed dofs (residual " + std::to_string(row.rhs) + ")");
    }
  }
  rows = std::move(kept);
}

void add_friction_rows(const std::vector<DofRecord>& records, std::vector<Row>& rows) {
  const size_t count = rows.size();
  for (size_t i = 0; i < count; ++i) {
    // A zero coefficient or bound holds nothing: no row, so that mu = 0 is the frictionless
    // problem, which refuses a body nothing else holds (a row pinned at 0 would let it pass
    // the coarse space's check and float along the tangent).
    if (rows[i].kind != RowKind::contact || !(rows[i].law_value > 0)) continue;
    std::vector<Row> pair;
    for (const RowAt& slip : rows[i].geometry->slip_rows()) {
      Row row{{}, 0.0, RowKind::friction, false, rows[i].geometry, static_cast<int>(i), rows[i].law_value};
      for (size_t k = 0; k < slip.dofs.size(); ++k) {
        if (slip.coefficients[k] == 0) continue;
        const auto& [subdomain, dof] = slip.dofs[k];
        // A fixed dof leaves the row, its prescribed motion moving to the right-hand side
        // (it is there from the first load step on and adds nothing to later increments). In
        // Total FETI too: its Dirichlet row already holds it, and a row on it alone would
        // repeat that row (B would lose full rank).
        if (const DofRecord* fixed = fixed_record(records, subdomain, dof))
          row.rhs -= slip.coefficients[k] * fixed->value;
        else
          row.entries.push_back({subdomain, dof, slip.coefficients[k]});
      }
      pair.push_back(std::move(row));
    }
    const auto empty = std::count_if(pair.begin(), pair.end(), [](const Row& r) { return r.entries.empty(); });
    if (empty == static_cast<long>(pair.size())) continue;  // a slave that cannot slip
    // Both rows of a 3D pair or none: their multipliers share one disc, and a lone row
    // would make the friction anisotropic.
    if (empty > 0)
      throw InputError("friction: the slave node at (" + std::to_string(rows[i].geometry->slave_position()[0]) + ", " +
                       std::to_string(rows[i].geometry->slave_position()[1]) + ", " +
                       std::to_string(rows[i].geometry->slave_position()[2]) +
                       ") has prescribed motion along one tangent of its contact and not the other: "
                       "fix all its components or none");
    for (Row& row : pair) rows.push_back(std::move(row));
  }
}

}  // namespace ffeti

#include "feti/constraints.h"

#include "feti/errors.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace ffeti {
namespace {

struct Row {
  std::vector<ConstraintEntry> entries;
  double rhs = 0;
  RowKind kind = RowKind::gluing;
  bool equality = true;
};

/// A dof located by body, component and its node's coordinates snapped to a fine grid.
struct LocatedDof {
  int body, component;
  long long ix, iy;
  int subdomain, dof;
  auto position() const { return std::tie(component, ix, iy); }
  auto key() const { return std::tie(body, component, ix, iy); }
  bool operator<(const LocatedDof& o) const {
    return std::tie(body, component, ix, iy, subdomain, dof) <
           std::tie(o.body, o.component, o.ix, o.iy, o.subdomain, o.dof);
  }
};

/// Coordinates closer than this are the same node (relative to the model's size).
double snapping_length(const std::vector<SubdomainInput>& subdomains) {
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (const auto& s : subdomains)
    for (size_t i = 0; i < s.x.size(); ++i) {
      lo_x = std::min(lo_x, s.x[i]), hi_x = std::max(hi_x, s.x[i]);
      lo_y = std::min(lo_y, s.y[i]), hi_y = std::max(hi_y, s.y[i]);
    }
  const double diagonal = std::hypot(hi_x - lo_x, hi_y - lo_y);
  return 1e-9 * (diagonal > 0 ? diagonal : 1.0);
}

LocatedDof locate(const std::vector<SubdomainInput>& subdomains, int s, int dof, double snap) {
  const SubdomainInput& sub = subdomains[static_cast<size_t>(s)];
  const auto i = static_cast<size_t>(dof);
  return {sub.body, sub.component.empty() ? 0 : sub.component[i], std::llround(sub.x[i] / snap),
          std::llround(sub.y[i] / snap), s, dof};
}

struct DirichletLookup {
  std::vector<std::vector<char>> is_fixed;
  std::vector<std::vector<double>> value;
  explicit DirichletLookup(const std::vector<SubdomainInput>& subdomains) {
    for (const auto& sub : subdomains) {
      is_fixed.emplace_back(sub.x.size(), 0);
      value.emplace_back(sub.x.size(), 0.0);
      for (size_t k = 0; k < sub.dirichlet_dofs.size(); ++k) {
        const auto i = static_cast<size_t>(sub.dirichlet_dofs[k]);
        is_fixed.back()[i] = 1;
        value.back()[i] = sub.dirichlet_values.empty() ? 0.0 : sub.dirichlet_values[k];
      }
    }
  }
  bool fixed(int s, int dof) const {
    return is_fixed[static_cast<size_t>(s)][static_cast<size_t>(dof)] != 0;
  }
};

void add_gluing_rows(const std::vector<SubdomainInput>& subdomains, const DirichletLookup& dirichlet,
                     double snap, std::vector<Row>& rows) {
  std::vector<LocatedDof> dofs;
  for (int s = 0; s < static_cast<int>(subdomains.size()); ++s)
    for (int i = 0; i < static_cast<int>(subdomains[static_cast<size_t>(s)].x.size()); ++i)
      dofs.push_back(locate(subdomains, s, i, snap));
  std::sort(dofs.begin(), dofs.end());
  for (size_t first = 0; first < dofs.size();) {
    size_t last = first + 1;
    while (last < dofs.size() && dofs[last].key() == dofs[first].key()) ++last;
    std::vector<const LocatedDof*> free_copies, fixed_copies;
    for (size_t k = first; k < last; ++k) {
      if (k > first && dofs[k].subdomain == dofs[k - 1].subdomain)
        throw InputError("X[" + std::to_string(dofs[k].subdomain) + "], Y[" +
                         std::to_string(dofs[k].subdomain) + "]: dofs " +
                         std::to_string(dofs[k - 1].dof) + " and " + std::to_string(dofs[k].dof) +
                         " of one subdomain share a position and component");
      (dirichlet.fixed(dofs[k].subdomain, dofs[k].dof) ? fixed_copies : free_copies)
          .push_back(&dofs[k]);
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

void add_dirichlet_rows(const std::vector<SubdomainInput>& subdomains, std::vector<Row>& rows) {
  for (int s = 0; s < static_cast<int>(subdomains.size()); ++s) {
    const SubdomainInput& sub = subdomains[static_cast<size_t>(s)];
    for (size_t k = 0; k < sub.dirichlet_dofs.size(); ++k)
      rows.push_back({{{s, sub.dirichlet_dofs[k], 1.0}},
                      sub.dirichlet_values.empty() ? 0.0 : sub.dirichlet_values[k],
                      RowKind::dirichlet, true});
  }
}

std::vector<LocatedDof> located_set(const std::vector<SubdomainInput>& subdomains,
                                    const std::vector<std::vector<int>>& dofs, double snap) {
  std::vector<LocatedDof> located;
  for (int s = 0; s < static_cast<int>(dofs.size()); ++s)
    for (int dof : dofs[static_cast<size_t>(s)]) located.push_back(locate(subdomains, s, dof, snap));
  std::sort(located.begin(), located.end());
  return located;
}

void add_contact_rows(const std::vector<SubdomainInput>& subdomains,
                      const NodeToNodeContact& contact, double snap, std::vector<Row>& rows) {
  std::vector<LocatedDof> slaves = located_set(subdomains, contact.slave_dofs, snap);
  // One row per physical slave node: its copies in other subdomains are glued to it.
  slaves.erase(std::unique(slaves.begin(), slaves.end(),
                           [](const LocatedDof& a, const LocatedDof& b) { return a.key() == b.key(); }),
               slaves.end());
  std::vector<LocatedDof> masters = located_set(subdomains, contact.master_dofs, snap);
  const auto by_position = [](const LocatedDof& a, const LocatedDof& b) {
    return a.position() < b.position();
  };
  std::sort(masters.begin(), masters.end(), [&](const LocatedDof& a, const LocatedDof& b) {
    return std::tie(a.component, a.ix, a.iy, a.subdomain, a.dof) <
           std::tie(b.component, b.ix, b.iy, b.subdomain, b.dof);
  });
  for (const LocatedDof& slave : slaves) {
    auto range = std::equal_range(masters.begin(), masters.end(), slave, by_position);
    auto master = std::find_if(range.first, range.second,
                               [&](const LocatedDof& m) { return m.body != slave.body; });
    if (master == range.second) {
      const SubdomainInput& sub = subdomains[static_cast<size_t>(slave.subdomain)];
      throw InputError("contactSlave[" + std::to_string(slave.subdomain) + "]: dof " +
                       std::to_string(slave.dof) + " at (" +
                       std::to_string(sub.x[static_cast<size_t>(slave.dof)]) + ", " +
                       std::to_string(sub.y[static_cast<size_t>(slave.dof)]) +
                       ") has no master dof of another body at the same position "
                       "(node-to-node contact needs matching meshes)");
    }
    rows.push_back({{{slave.subdomain, slave.dof, 1.0}, {master->subdomain, master->dof, -1.0}},
                    contact.gap, RowKind::contact, false});
  }
}

/// FETI-1: known Dirichlet values move to the right-hand side.
void substitute_dirichlet(const DirichletLookup& dirichlet, std::vector<Row>& rows) {
  std::vector<Row> kept;
  for (Row& row : rows) {
    std::vector<ConstraintEntry> free_entries;
    for (const ConstraintEntry& e : row.entries) {
      if (dirichlet.fixed(e.subdomain, e.dof))
        row.rhs -= e.coefficient *
                   dirichlet.value[static_cast<size_t>(e.subdomain)][static_cast<size_t>(e.dof)];
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

}  // namespace

int Constraints::count(RowKind k) const {
  return static_cast<int>(std::count(kind.begin(), kind.end(), k));
}

Constraints build_constraints(const std::vector<SubdomainInput>& subdomains,
                              const NodeToNodeContact& contact, FetiVariant variant) {
  const double snap = snapping_length(subdomains);
  const DirichletLookup dirichlet(subdomains);
  std::vector<Row> rows;
  add_gluing_rows(subdomains, dirichlet, snap, rows);
  if (variant == FetiVariant::tfeti) add_dirichlet_rows(subdomains, rows);
  add_contact_rows(subdomains, contact, snap, rows);
  if (variant == FetiVariant::feti1) substitute_dirichlet(dirichlet, rows);

  std::stable_partition(rows.begin(), rows.end(), [](const Row& r) { return r.equality; });
  Constraints result;
  for (const Row& row : rows) {
    result.entries.insert(result.entries.end(), row.entries.begin(), row.entries.end());
    result.row_start.push_back(static_cast<int>(result.entries.size()));
    result.rhs.push_back(row.rhs);
    result.kind.push_back(row.kind);
    result.equality_rows += row.equality ? 1 : 0;
  }
  return result;
}

std::vector<LocalConstraints> split_by_subdomain(const Constraints& constraints,
                                                 const std::vector<Eigen::Index>& sizes) {
  std::vector<std::vector<Eigen::Triplet<double, int>>> triplets(sizes.size());
  std::vector<LocalConstraints> local(sizes.size());
  for (int row = 0; row < constraints.rows(); ++row)
    for (int k = constraints.row_start[static_cast<size_t>(row)];
         k < constraints.row_start[static_cast<size_t>(row) + 1]; ++k) {
      const ConstraintEntry& e = constraints.entries[static_cast<size_t>(k)];
      LocalConstraints& block = local[static_cast<size_t>(e.subdomain)];
      if (block.rows.empty() || block.rows.back() != row) block.rows.push_back(row);
      triplets[static_cast<size_t>(e.subdomain)].emplace_back(
          static_cast<int>(block.rows.size()) - 1, e.dof, e.coefficient);
    }
  for (size_t s = 0; s < sizes.size(); ++s) {
    local[s].B.resize(static_cast<Eigen::Index>(local[s].rows.size()), sizes[s]);
    local[s].B.setFromTriplets(triplets[s].begin(), triplets[s].end());
    local[s].B.makeCompressed();
  }
  return local;
}

}  // namespace ffeti

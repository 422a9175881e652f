#include "feti/constraints.h"

#include "base/errors.h"

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
  ContactRowGeometry geometry{};
};

/// A record with its node snapped to a grid of the snapping length.
struct Located {
  const DofRecord* record;
  long long ix, iy;
  auto key() const { return std::tie(record->body, record->component, ix, iy); }
  auto position() const { return std::tie(record->component, ix, iy); }
};

std::vector<Located> locate(const std::vector<DofRecord>& records, double snap,
                            bool (*select)(const DofRecord&)) {
  std::vector<Located> located;
  for (const DofRecord& r : records)
    if (select(r)) located.push_back({&r, std::llround(r.x / snap), std::llround(r.y / snap)});
  std::stable_sort(located.begin(), located.end(), [](const Located& a, const Located& b) {
    return std::tie(a.record->body, a.record->component, a.ix, a.iy, a.record->subdomain, a.record->dof) <
           std::tie(b.record->body, b.record->component, b.ix, b.iy, b.record->subdomain, b.record->dof);
  });
  return located;
}

void add_gluing_rows(const std::vector<DofRecord>& records, double snap, std::vector<Row>& rows) {
  const std::vector<Located> dofs = locate(records, snap, [](const DofRecord&) { return true; });
  for (size_t first = 0; first < dofs.size();) {
    size_t last = first + 1;
    while (last < dofs.size() && dofs[last].key() == dofs[first].key()) ++last;
    std::vector<const DofRecord*> free_copies, fixed_copies;
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

/// The slave dofs, one copy per physical dof: other copies are glued to it.
std::vector<Located> unique_slaves(const std::vector<DofRecord>& records, double snap) {
  std::vector<Located> slaves = locate(records, snap, [](const DofRecord& r) { return r.slave; });
  slaves.erase(std::unique(slaves.begin(), slaves.end(),
                           [](const Located& a, const Located& b) { return a.key() == b.key(); }),
               slaves.end());
  return slaves;
}

void add_node_to_node_rows(const std::vector<DofRecord>& records, double gap, double snap, std::vector<Row>& rows) {
  const std::vector<Located> slaves = unique_slaves(records, snap);
  std::vector<Located> masters = locate(records, snap, [](const DofRecord& r) { return r.master; });
  std::stable_sort(masters.begin(), masters.end(),
                   [](const Located& a, const Located& b) { return a.position() < b.position(); });
  const auto by_position = [](const Located& a, const Located& b) { return a.position() < b.position(); };
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
    ContactRowGeometry geometry;
    geometry.slave[0] = {slave.record->subdomain, slave.record->dof};
    rows.push_back({{{slave.record->subdomain, slave.record->dof, 1.0},
                     {master->record->subdomain, master->record->dof, -1.0}},
                    gap + slave.record->gap, RowKind::contact, false, geometry});
  }
}

/// A slave node of the node-to-segment or obstacle contact: its two dofs and position.
struct SlaveNode {
  const DofRecord* x_dof;
  const DofRecord* y_dof;
};

std::vector<SlaveNode> slave_nodes(const std::vector<DofRecord>& records, double snap) {
  const std::vector<Located> slaves = unique_slaves(records, snap);  // sorted by key(): component 0 first
  std::vector<SlaveNode> nodes;
  for (const Located& s : slaves) {
    if (s.record->component != 0) continue;
    const auto wanted = std::make_tuple(s.record->body, 1, s.ix, s.iy);  // the y dof of the same node
    const auto partner = std::lower_bound(slaves.begin(), slaves.end(), wanted,
                                          [](const Located& o, const auto& key) { return o.key() < key; });
    if (partner == slaves.end() || partner->key() != wanted)
      throw InputError("contactSlave[" + std::to_string(s.record->subdomain) + "]: dof " +
                       std::to_string(s.record->dof) + " has no dof of component 1 at its node: list both "
                       "components of each slave node for node-to-segment or obstacle contact");
    nodes.push_back({s.record, partner->record});
  }
  return nodes;
}

/// Master segments bucketed in a uniform grid (cells about the mean segment length), so that
/// the nearest segment of a slave is found ring by ring around its cell, in time independent
/// of the number of segments, instead of testing every segment.
class SegmentGrid {
 public:
  explicit SegmentGrid(const std::vector<SegmentRecord>& segments) : segments_(segments) {
    double length = 0;
    lo_x_ = lo_y_ = INFINITY;
    double hi_x = -INFINITY, hi_y = -INFINITY;
    for (const SegmentRecord& seg : segments) {
      length += std::hypot(seg.bx - seg.ax, seg.by - seg.ay);
      lo_x_ = std::min({lo_x_, seg.ax, seg.bx}), hi_x = std::max({hi_x, seg.ax, seg.bx});
      lo_y_ = std::min({lo_y_, seg.ay, seg.by}), hi_y = std::max({hi_y, seg.ay, seg.by});
    }
    constexpr double kMaxCellsPerSide = 2048;
    cell_ = std::max({length / static_cast<double>(segments.size()), (hi_x - lo_x_) / kMaxCellsPerSide,
                      (hi_y - lo_y_) / kMaxCellsPerSide, 1e-300});
    nx_ = static_cast<int>((hi_x - lo_x_) / cell_) + 1, ny_ = static_cast<int>((hi_y - lo_y_) / cell_) + 1;
    cells_.resize(static_cast<size_t>(nx_) * static_cast<size_t>(ny_));
    for (size_t k = 0; k < segments.size(); ++k) {
      const SegmentRecord& seg = segments[k];
      for (int j = cell_y(std::min(seg.ay, seg.by)); j <= cell_y(std::max(seg.ay, seg.by)); ++j)
        for (int i = cell_x(std::min(seg.ax, seg.bx)); i <= cell_x(std::max(seg.ax, seg.bx)); ++i)
          cells_[index(i, j)].push_back(static_cast<int>(k));
    }
  }

  /// The segment of a body other than `body` nearest to (x, y), closer than `reach`; of
  /// equally near ones the smallest (subdomain, dofs), so that the choice does not depend
  /// on the order of the segments (which follows the ranks). nullptr if there is none.
  const SegmentRecord* nearest(double x, double y, int body, double reach) const {
    const SegmentRecord* best = nullptr;
    double best_distance = reach;
    const auto visit = [&](int i, int j) {
      if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return;
      for (int k : cells_[index(i, j)]) {
        const SegmentRecord& seg = segments_[static_cast<size_t>(k)];
        if (seg.body == body) continue;
        const double dx = seg.bx - seg.ax, dy = seg.by - seg.ay, length_sq = dx * dx + dy * dy;
        const double xi = std::clamp(((x - seg.ax) * dx + (y - seg.ay) * dy) / length_sq, 0.0, 1.0);
        const double distance = std::hypot(x - (seg.ax + xi * dx), y - (seg.ay + xi * dy));
        if (distance < best_distance ||
            (best && distance == best_distance && std::tie(seg.subdomain, seg.dofs) < std::tie(best->subdomain, best->dofs)))
          best = &seg, best_distance = distance;
      }
    };
    // The cells at Chebyshev distance r from the point's (clamped) cell, ring after ring:
    // those of ring r lie at least (r - 1) cells from the point.
    const int ci = cell_x(x), cj = cell_y(y);
    for (int r = 0; r <= std::max(nx_, ny_) && (r - 1) * cell_ <= best_distance; ++r) {
      if (r == 0) {
        visit(ci, cj);
        continue;
      }
      for (int i = std::max(ci - r, 0); i <= std::min(ci + r, nx_ - 1); ++i) visit(i, cj - r), visit(i, cj + r);
      for (int j = std::max(cj - r + 1, 0); j <= std::min(cj + r - 1, ny_ - 1); ++j) visit(ci - r, j), visit(ci + r, j);
    }
    return best;
  }

 private:
  int cell_x(double x) const { return std::clamp(static_cast<int>(std::floor((x - lo_x_) / cell_)), 0, nx_ - 1); }
  int cell_y(double y) const { return std::clamp(static_cast<int>(std::floor((y - lo_y_) / cell_)), 0, ny_ - 1); }
  size_t index(int i, int j) const { return static_cast<size_t>(j) * static_cast<size_t>(nx_) + static_cast<size_t>(i); }

  const std::vector<SegmentRecord>& segments_;
  double lo_x_, lo_y_, cell_;
  int nx_, ny_;
  std::vector<std::vector<int>> cells_;
};

void add_node_to_segment_rows(const std::vector<DofRecord>& records, const std::vector<SegmentRecord>& segments,
                              const ContactInput& contact, double snap, std::vector<Row>& rows) {
  const SegmentGrid grid(segments);
  for (const SlaveNode& node : slave_nodes(records, snap)) {
    const double sx = node.x_dof->x, sy = node.x_dof->y;
    const SegmentRecord* best = grid.nearest(sx, sy, node.x_dof->body, contact.search_distance);
    if (!best) continue;  // no master segment within reach: no contact possible here
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::node_to_segment;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    for (size_t k = 0; k < 4; ++k) geometry.master[k] = {best->subdomain, best->dofs[k]};
    geometry.s = {sx, sy}, geometry.a = {best->ax, best->ay}, geometry.b = {best->bx, best->by};
    const LinearizedRow linear = node_to_segment_row(geometry.s, geometry.a, geometry.b);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry};
    const std::array<int, 2> dofs[6] = {geometry.slave[0], geometry.slave[1], geometry.master[0],
                                        geometry.master[1], geometry.master[2], geometry.master[3]};
    for (size_t k = 0; k < 6; ++k)
      if (linear.coefficients[k] != 0) row.entries.push_back({dofs[k][0], dofs[k][1], linear.coefficients[k]});
    rows.push_back(std::move(row));
  }
}

void add_obstacle_rows(const std::vector<DofRecord>& records, const ContactInput& contact, double snap,
                       std::vector<Row>& rows) {
  const double norm = std::hypot(contact.obstacle_normal[0], contact.obstacle_normal[1]);
  if (!(norm > 0)) throw InputError("obstacle: the normal (entries 3 and 4) must not be zero");
  const double nx = contact.obstacle_normal[0] / norm, ny = contact.obstacle_normal[1] / norm;
  for (const SlaveNode& node : slave_nodes(records, snap)) {
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::obstacle;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    geometry.s = {node.x_dof->x, node.x_dof->y};
    geometry.a = contact.obstacle_point, geometry.b = {nx, ny};
    const LinearizedRow linear = obstacle_row(geometry.s, geometry.a, geometry.b);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry};
    for (size_t k = 0; k < 2; ++k)
      if (linear.coefficients[k] != 0) row.entries.push_back({geometry.slave[k][0], geometry.slave[k][1], linear.coefficients[k]});
    rows.push_back(std::move(row));
  }
}

/// FETI-1: known Dirichlet values move to the right-hand side.
void substitute_dirichlet(const std::vector<DofRecord>& records, std::vector<Row>& rows) {
  const auto find = [&](int s, int dof) {
    auto it = std::lower_bound(records.begin(), records.end(), std::make_pair(s, dof),
                               [](const DofRecord& r, const std::pair<int, int>& key) {
                                 return std::make_pair(r.subdomain, r.dof) < key;
                               });
    return it != records.end() && it->subdomain == s && it->dof == dof && it->fixed ? &*it : nullptr;
  };
  std::vector<Row> kept;
  for (Row& row : rows) {
    std::vector<ConstraintEntry> free_entries;
    for (const ConstraintEntry& e : row.entries) {
      if (const DofRecord* fixed = find(e.subdomain, e.dof))
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

/// Subdomains whose inflated boxes overlap each cell of a uniform grid over all boxes:
/// finds the boxes containing a point without testing all of them.
class BoxGrid {
 public:
  BoxGrid(const std::vector<BoundingBox>& boxes, double margin) : boxes_(boxes), margin_(margin) {
    lo_x_ = lo_y_ = INFINITY;
    double hi_x = -INFINITY, hi_y = -INFINITY;
    for (const BoundingBox& b : boxes) {
      lo_x_ = std::min(lo_x_, b.x0), lo_y_ = std::min(lo_y_, b.y0);
      hi_x = std::max(hi_x, b.x1), hi_y = std::max(hi_y, b.y1);
    }
    cells_ = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(boxes.size())))));
    cell_x_ = std::max((hi_x - lo_x_) / cells_, margin), cell_y_ = std::max((hi_y - lo_y_) / cells_, margin);
    members_.resize(static_cast<size_t>(cells_ * cells_));
    for (int s = 0; s < static_cast<int>(boxes.size()); ++s) {
      const BoundingBox& b = boxes[static_cast<size_t>(s)];
      for (int j = cell(b.y0 - margin, lo_y_, cell_y_); j <= cell(b.y1 + margin, lo_y_, cell_y_); ++j)
        for (int i = cell(b.x0 - margin, lo_x_, cell_x_); i <= cell(b.x1 + margin, lo_x_, cell_x_); ++i)
          members_[static_cast<size_t>(j * cells_ + i)].push_back(s);
    }
  }
  template <class F>
  void for_each_containing(double x, double y, F&& visit) const {
    const int i = cell(x, lo_x_, cell_x_), j = cell(y, lo_y_, cell_y_);
    for (int s : members_[static_cast<size_t>(j * cells_ + i)]) {
      const BoundingBox& b = boxes_[static_cast<size_t>(s)];
      if (x >= b.x0 - margin_ && x <= b.x1 + margin_ && y >= b.y0 - margin_ && y <= b.y1 + margin_) visit(s);
    }
  }

 private:
  int cell(double v, double lo, double width) const {
    return std::clamp(static_cast<int>(std::floor((v - lo) / width)), 0, cells_ - 1);
  }
  const std::vector<BoundingBox>& boxes_;
  double margin_, lo_x_, lo_y_, cell_x_, cell_y_;
  int cells_;
  std::vector<std::vector<int>> members_;
};

}  // namespace

LinearizedRow node_to_segment_row(const Point& s, const Point& a, const Point& b, bool clamp_xi) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
  double xi = ((s[0] - a[0]) * dx + (s[1] - a[1]) * dy) / (length * length);
  if (clamp_xi) xi = std::clamp(xi, 0.0, 1.0);
  const double nx = dy / length, ny = -dx / length;  // outward: the body lies on the left
  const double px = a[0] + xi * dx, py = a[1] + xi * dy;
  return {{-nx, -ny, (1 - xi) * nx, (1 - xi) * ny, xi * nx, xi * ny}, nx * (s[0] - px) + ny * (s[1] - py)};
}

LinearizedRow obstacle_row(const Point& s, const Point& point, const Point& normal) {
  return {{-normal[0], -normal[1], 0, 0, 0, 0}, normal[0] * (s[0] - point[0]) + normal[1] * (s[1] - point[1])};
}

BoundingBox bounding_box(const SubdomainInput& subdomain) {
  BoundingBox b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < subdomain.x.size(); ++i) {
    b.x0 = std::min(b.x0, subdomain.x[i]), b.x1 = std::max(b.x1, subdomain.x[i]);
    b.y0 = std::min(b.y0, subdomain.y[i]), b.y1 = std::max(b.y1, subdomain.y[i]);
  }
  return b;
}

double snapping_length(const std::vector<BoundingBox>& boxes) {
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (const BoundingBox& b : boxes) {
    lo_x = std::min(lo_x, b.x0), hi_x = std::max(hi_x, b.x1);
    lo_y = std::min(lo_y, b.y0), hi_y = std::max(hi_y, b.y1);
  }
  const double diagonal = std::hypot(hi_x - lo_x, hi_y - lo_y);
  return 1e-9 * (diagonal > 0 && std::isfinite(diagonal) ? diagonal : 1.0);
}

std::vector<DofRecord> constraint_candidates(const std::vector<SubdomainInput>& local,
                                             const std::vector<int>& global_ids,
                                             const ContactInput& local_contact,
                                             const std::vector<BoundingBox>& boxes,
                                             const std::vector<int>& bodies, double snap) {
  const BoxGrid grid(boxes, 4 * snap);
  std::vector<DofRecord> records;
  for (size_t k = 0; k < local.size(); ++k) {
    const SubdomainInput& sub = local[k];
    const int s = global_ids[k];
    const size_t n = sub.x.size();
    std::vector<char> fixed(n, 0), slave(n, 0), master(n, 0);
    std::vector<double> value(n, 0.0);
    const std::vector<double>* gap = local_contact.gap_field.empty() || local_contact.gap_field[k].empty()
                                         ? nullptr : &local_contact.gap_field[k];
    for (size_t i = 0; i < sub.dirichlet_dofs.size(); ++i) {
      fixed[static_cast<size_t>(sub.dirichlet_dofs[i])] = 1;
      value[static_cast<size_t>(sub.dirichlet_dofs[i])] = sub.dirichlet_values.empty() ? 0.0 : sub.dirichlet_values[i];
    }
    if (!local_contact.slave_dofs.empty())
      for (int dof : local_contact.slave_dofs[k]) slave[static_cast<size_t>(dof)] = 1;
    if (!local_contact.master_dofs.empty())
      for (int dof : local_contact.master_dofs[k]) master[static_cast<size_t>(dof)] = 1;
    for (size_t i = 0; i < n; ++i) {
      bool shared = false;
      grid.for_each_containing(sub.x[i], sub.y[i], [&](int other) {
        shared = shared || (other != s && bodies[static_cast<size_t>(other)] == sub.body);
      });
      if (shared || fixed[i] || slave[i] || master[i])
        records.push_back({s, static_cast<int>(i), sub.body, sub.component.empty() ? 0 : sub.component[i],
                           sub.x[i], sub.y[i], fixed[i] != 0, slave[i] != 0, master[i] != 0, value[i],
                           gap ? (*gap)[i] : 0.0});
    }
  }
  return records;
}

std::vector<double> pack(const std::vector<DofRecord>& records) {
  std::vector<double> packed;
  packed.reserve(records.size() * 9);
  for (const DofRecord& r : records) {
    const double flags = (r.fixed ? 1 : 0) + (r.slave ? 2 : 0) + (r.master ? 4 : 0);
    packed.insert(packed.end(), {double(r.subdomain), double(r.dof), double(r.body), double(r.component),
                                 r.x, r.y, flags, r.value, r.gap});
  }
  return packed;
}

std::vector<DofRecord> unpack(const std::vector<double>& packed) {
  std::vector<DofRecord> records;
  for (size_t k = 0; k + 9 <= packed.size(); k += 9) {
    const int flags = static_cast<int>(packed[k + 6]);
    records.push_back({static_cast<int>(packed[k]), static_cast<int>(packed[k + 1]), static_cast<int>(packed[k + 2]),
                       static_cast<int>(packed[k + 3]), packed[k + 4], packed[k + 5], (flags & 1) != 0,
                       (flags & 2) != 0, (flags & 4) != 0, packed[k + 7], packed[k + 8]});
  }
  return records;
}

std::vector<SegmentRecord> segment_records(const std::vector<SubdomainInput>& local,
                                           const std::vector<int>& global_ids, const ContactInput& local_contact) {
  std::vector<SegmentRecord> segments;
  for (size_t k = 0; k < local_contact.master_segments.size(); ++k)
    for (const auto& dofs : local_contact.master_segments[k]) {
      const SubdomainInput& sub = local[k];
      const auto a = static_cast<size_t>(dofs[0]), b = static_cast<size_t>(dofs[2]);
      segments.push_back({global_ids[k], sub.body, dofs, sub.x[a], sub.y[a], sub.x[b], sub.y[b]});
    }
  return segments;
}

std::vector<double> pack(const std::vector<SegmentRecord>& segments) {
  std::vector<double> packed;
  for (const SegmentRecord& s : segments)
    packed.insert(packed.end(), {double(s.subdomain), double(s.body), double(s.dofs[0]), double(s.dofs[1]),
                                 double(s.dofs[2]), double(s.dofs[3]), s.ax, s.ay, s.bx, s.by});
  return packed;
}

std::vector<SegmentRecord> unpack_segments(const std::vector<double>& packed) {
  std::vector<SegmentRecord> segments;
  for (size_t k = 0; k + 10 <= packed.size(); k += 10)
    segments.push_back({static_cast<int>(packed[k]), static_cast<int>(packed[k + 1]),
                        {static_cast<int>(packed[k + 2]), static_cast<int>(packed[k + 3]),
                         static_cast<int>(packed[k + 4]), static_cast<int>(packed[k + 5])},
                        packed[k + 6], packed[k + 7], packed[k + 8], packed[k + 9]});
  return segments;
}

int Constraints::count(RowKind k) const {
  return static_cast<int>(std::count(kind.begin(), kind.end(), k));
}

Constraints build_constraints(std::vector<DofRecord> records, const std::vector<SegmentRecord>& segments,
                              const ContactInput& contact, FetiVariant variant, double snap) {
  std::sort(records.begin(), records.end(), [](const DofRecord& a, const DofRecord& b) {
    return std::make_pair(a.subdomain, a.dof) < std::make_pair(b.subdomain, b.dof);
  });
  std::vector<Row> rows;
  add_gluing_rows(records, snap, rows);
  if (variant == FetiVariant::tfeti) add_dirichlet_rows(records, rows);
  if (!segments.empty()) add_node_to_segment_rows(records, segments, contact, snap, rows);
  if (contact.obstacle) add_obstacle_rows(records, contact, snap, rows);
  if (segments.empty() && !contact.obstacle) add_node_to_node_rows(records, contact.gap, snap, rows);
  if (variant == FetiVariant::feti1) substitute_dirichlet(records, rows);

  std::stable_partition(rows.begin(), rows.end(), [](const Row& r) { return r.equality; });
  Constraints result;
  for (const Row& row : rows) {
    result.entries.insert(result.entries.end(), row.entries.begin(), row.entries.end());
    result.row_start.push_back(static_cast<int>(result.entries.size()));
    result.rhs.push_back(row.rhs);
    result.kind.push_back(row.kind);
    result.equality_rows += row.equality ? 1 : 0;
    if (!row.equality) result.geometry.push_back(row.geometry);
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
  return build_constraints(constraint_candidates(subdomains, ids, contact, boxes, bodies, snap),
                           segment_records(subdomains, ids, contact), contact, variant, snap);
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

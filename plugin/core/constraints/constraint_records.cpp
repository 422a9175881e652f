#include "constraints/constraint_records.h"

#include "base/parallel_for.h"
#include "constraints/contact/contact_discretization.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace ffeti {
namespace {

/// Subdomains whose inflated boxes overlap each cell of a uniform grid over all boxes:
/// finds the boxes containing a point without testing all of them. The grid spans every
/// axis the boxes extend along: a 2D grid over x and y left each cell of a 3D scene with all
/// the boxes stacked above it (32 to test for every node of the 8192 boxes of two cubes).
class BoxGrid {
 public:
  BoxGrid(const std::vector<BoundingBox>& boxes, double margin) : boxes_(boxes), margin_(margin) {
    std::array<double, 3> hi{-INFINITY, -INFINITY, -INFINITY};
    lo_.fill(INFINITY);
    for (const BoundingBox& b : boxes)
      for (int a = 0; a < 3; ++a) lo_[a] = std::min(lo_[a], low(b, a)), hi[a] = std::max(hi[a], high(b, a));
    if (boxes.empty()) lo_.fill(0.0), hi.fill(0.0);
    const int axes = hi[2] > lo_[2] ? 3 : 2;  // z = 0 in a plane problem
    const int per_axis = std::max(1, static_cast<int>(std::ceil(std::pow(static_cast<double>(boxes.size()), 1.0 / axes))));
    for (int a = 0; a < 3; ++a) {
      cells_[a] = a < axes ? per_axis : 1;
      width_[a] = a < axes ? std::max((hi[a] - lo_[a]) / cells_[a], margin) : 1.0;
      if (a >= axes) lo_[a] = 0.0;
    }
    members_.resize(static_cast<size_t>(cells_[0] * cells_[1] * cells_[2]));
    for (int s = 0; s < static_cast<int>(boxes.size()); ++s) {
      const BoundingBox& b = boxes[static_cast<size_t>(s)];
      std::array<int, 3> first{}, last{};
      for (int a = 0; a < 3; ++a) first[a] = cell(low(b, a) - margin, a), last[a] = cell(high(b, a) + margin, a);
      for (int k = first[2]; k <= last[2]; ++k)
        for (int j = first[1]; j <= last[1]; ++j)
          for (int i = first[0]; i <= last[0]; ++i) members_[index(i, j, k)].push_back(s);
    }
  }
  /// Every box whose inflated extent holds the point (z = 0 in a plane problem).
  template <class F>
  void for_each_containing(double x, double y, double z, F&& visit) const {
    for (int s : members_[index(cell(x, 0), cell(y, 1), cell(z, 2))]) {
      const BoundingBox& b = boxes_[static_cast<size_t>(s)];
      if (x >= b.x0 - margin_ && x <= b.x1 + margin_ && y >= b.y0 - margin_ && y <= b.y1 + margin_ &&
          z >= b.z0 - margin_ && z <= b.z1 + margin_)
        visit(s);
    }
  }

 private:
  static double low(const BoundingBox& b, int axis) { return axis == 0 ? b.x0 : axis == 1 ? b.y0 : b.z0; }
  static double high(const BoundingBox& b, int axis) { return axis == 0 ? b.x1 : axis == 1 ? b.y1 : b.z1; }
  int cell(double v, int axis) const {
    return std::clamp(static_cast<int>(std::floor((v - lo_[axis]) / width_[axis])), 0, cells_[axis] - 1);
  }
  size_t index(int i, int j, int k) const { return static_cast<size_t>((k * cells_[1] + j) * cells_[0] + i); }
  const std::vector<BoundingBox>& boxes_;
  double margin_;
  std::array<double, 3> lo_{}, width_{};
  std::array<int, 3> cells_{};
  std::vector<std::vector<int>> members_;
};

/// The dofs of the other components at the node of a slave or master dof: node-to-node
/// friction slips along them. The other kinds list every component of their slave nodes
/// and take no master dofs, so they gain nothing; and a dof without a copy in another
/// subdomain forms no gluing row: recording it changes no other row.
std::vector<char> node_partners(const SubdomainInput& sub, const std::vector<char>& slave,
                                const std::vector<char>& master, double snap) {
  const size_t n = sub.x.size();
  std::vector<char> partner(n, 0);
  using Key = std::array<long long, 3>;
  const auto key = [&](size_t i) {
    return Key{std::llround(sub.x[i] / snap), std::llround(sub.y[i] / snap), std::llround((sub.z.empty() ? 0.0 : sub.z[i]) / snap)};
  };
  std::vector<std::pair<Key, size_t>> contact_nodes;
  for (size_t i = 0; i < n; ++i)
    if (slave[i] || master[i]) contact_nodes.push_back({key(i), i});
  std::sort(contact_nodes.begin(), contact_nodes.end());
  for (size_t i = 0; i < n; ++i) {
    const auto at = std::lower_bound(contact_nodes.begin(), contact_nodes.end(), std::make_pair(key(i), size_t{0}));
    partner[i] = at != contact_nodes.end() && at->first == key(i);
  }
  return partner;
}

}  // namespace

BoundingBox bounding_box(const SubdomainInput& subdomain) {
  BoundingBox b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < subdomain.x.size(); ++i) {
    b.x0 = std::min(b.x0, subdomain.x[i]), b.x1 = std::max(b.x1, subdomain.x[i]);
    b.y0 = std::min(b.y0, subdomain.y[i]), b.y1 = std::max(b.y1, subdomain.y[i]);
  }
  if (!subdomain.z.empty()) {
    b.z0 = INFINITY, b.z1 = -INFINITY;
    for (double z : subdomain.z) b.z0 = std::min(b.z0, z), b.z1 = std::max(b.z1, z);
  }
  return b;
}

double snapping_length(const std::vector<BoundingBox>& boxes) {
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY, lo_z = INFINITY, hi_z = -INFINITY;
  for (const BoundingBox& b : boxes) {
    lo_x = std::min(lo_x, b.x0), hi_x = std::max(hi_x, b.x1);
    lo_y = std::min(lo_y, b.y0), hi_y = std::max(hi_y, b.y1);
    lo_z = std::min(lo_z, b.z0), hi_z = std::max(hi_z, b.z1);
  }
  const double diagonal = std::hypot(hi_x - lo_x, hi_y - lo_y, hi_z - lo_z);
  return 1e-9 * (diagonal > 0 && std::isfinite(diagonal) ? diagonal : 1.0);
}

std::vector<DofRecord> constraint_candidates(const std::vector<SubdomainInput>& local,
                                             const std::vector<int>& global_ids,
                                             const ContactInput& local_contact,
                                             const std::vector<BoundingBox>& boxes,
                                             const std::vector<int>& bodies, double snap) {
  const BoxGrid grid(boxes, 4 * snap);
  // Per subdomain on the set-up's threads, joined in subdomain order.
  std::vector<std::vector<DofRecord>> per_subdomain(local.size());
  parallel_for_each(static_cast<int>(local.size()), 0, [&](int local_index) {
    const auto k = static_cast<size_t>(local_index);
    std::vector<DofRecord>& records = per_subdomain[k];
    const SubdomainInput& sub = local[k];
    const int s = global_ids[k];
    const size_t n = sub.x.size();
    std::vector<char> fixed(n, 0), slave(n, 0), master(n, 0);
    std::vector<double> value(n, 0.0);
    const std::vector<double>* gap = local_contact.gap_field.empty() || local_contact.gap_field[k].empty()
                                         ? nullptr : &local_contact.gap_field[k];
    // The law's value per slave: Coulomb's coefficient, or Tresca's bound.
    const bool tresca = local_contact.slip_bound >= 0;
    const auto& law_field = tresca ? local_contact.slip_bound_field : local_contact.friction_field;
    const double law_value = tresca ? local_contact.slip_bound : local_contact.friction;
    const std::vector<double>* friction = law_field.empty() || law_field[k].empty() ? nullptr : &law_field[k];
    for (size_t i = 0; i < sub.dirichlet_dofs.size(); ++i) {
      fixed[static_cast<size_t>(sub.dirichlet_dofs[i])] = 1;
      value[static_cast<size_t>(sub.dirichlet_dofs[i])] = sub.dirichlet_values.empty() ? 0.0 : sub.dirichlet_values[i];
    }
    if (!local_contact.slave_dofs.empty())
      for (int dof : local_contact.slave_dofs[k]) slave[static_cast<size_t>(dof)] = 1;
    // The list kinds' slaves and masters (mortar's slave faces' corners, node to node's masters).
    for (const ContactDiscretization* unit : kinds_with_lists()) unit->flag_dofs(local_contact, k, slave, master);
    const std::vector<char> partner = local_contact.has_friction() ? node_partners(sub, slave, master, snap)
                                                                   : std::vector<char>(n, 0);
    for (size_t i = 0; i < n; ++i) {
      bool shared = false;
      const double z = sub.z.empty() ? 0.0 : sub.z[i];
      grid.for_each_containing(sub.x[i], sub.y[i], z, [&](int other) {
        shared = shared || (other != s && bodies[static_cast<size_t>(other)] == sub.body);
      });
      if (shared || fixed[i] || slave[i] || master[i] || partner[i])
        records.push_back({s, static_cast<int>(i), sub.body, sub.component.empty() ? 0 : sub.component[i],
                           sub.x[i], sub.y[i], z, fixed[i] != 0, slave[i] != 0, master[i] != 0, value[i],
                           gap ? (*gap)[i] : 0.0, friction ? (*friction)[i] : law_value});
    }
  });
  size_t total = 0;
  for (const auto& part : per_subdomain) total += part.size();
  std::vector<DofRecord> records;
  records.reserve(total);
  for (const auto& part : per_subdomain) records.insert(records.end(), part.begin(), part.end());
  return records;
}

std::vector<double> pack(const std::vector<DofRecord>& records) {
  std::vector<double> packed;
  packed.reserve(records.size() * 11);
  for (const DofRecord& r : records) {
    const double flags = (r.fixed ? 1 : 0) + (r.slave ? 2 : 0) + (r.master ? 4 : 0);
    packed.insert(packed.end(), {double(r.subdomain), double(r.dof), double(r.body), double(r.component),
                                 r.x, r.y, r.z, flags, r.value, r.gap, r.law_value});
  }
  return packed;
}

void sort_by_subdomain_and_dof(std::vector<DofRecord>& records) {
  const auto before = [](const DofRecord& a, const DofRecord& b) {
    return std::make_pair(a.subdomain, a.dof) < std::make_pair(b.subdomain, b.dof);
  };
  if (!std::is_sorted(records.begin(), records.end(), before)) std::sort(records.begin(), records.end(), before);
}

std::vector<DofRecord> unpack(const std::vector<double>& packed) {
  std::vector<DofRecord> records;
  records.reserve(packed.size() / 11);
  for (size_t k = 0; k + 11 <= packed.size(); k += 11) {
    const int flags = static_cast<int>(packed[k + 7]);
    records.push_back({static_cast<int>(packed[k]), static_cast<int>(packed[k + 1]), static_cast<int>(packed[k + 2]),
                       static_cast<int>(packed[k + 3]), packed[k + 4], packed[k + 5], packed[k + 6], (flags & 1) != 0,
                       (flags & 2) != 0, (flags & 4) != 0, packed[k + 8], packed[k + 9], packed[k + 10]});
  }
  return records;
}

std::vector<SegmentRecord> segment_records(const std::vector<SubdomainInput>& local,
                                           const std::vector<int>& global_ids, const ContactInput& local_contact) {
  std::vector<SegmentRecord> segments;
  for (const ContactDiscretization* unit : kinds_with_lists()) unit->add_segments(local, global_ids, local_contact, segments);
  return segments;
}

void add_segment_records(const std::vector<std::vector<std::array<int, 4>>>& lists,
                         const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                         std::vector<SegmentRecord>& segments) {
  for (size_t k = 0; k < lists.size(); ++k)
    for (const auto& dofs : lists[k]) {
      const SubdomainInput& sub = local[k];
      const auto a = static_cast<size_t>(dofs[0]), b = static_cast<size_t>(dofs[2]);
      segments.push_back({global_ids[k], sub.body, dofs, sub.x[a], sub.y[a], sub.x[b], sub.y[b]});
    }
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

std::vector<FaceRecord> face_records(const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                                     const ContactInput& local_contact) {
  std::vector<FaceRecord> faces;
  for (const ContactDiscretization* unit : kinds_with_lists()) unit->add_faces(local, global_ids, local_contact, faces);
  // The master faces first, each kind's in its order (the faces' grid and mortar's surface read them so).
  std::stable_partition(faces.begin(), faces.end(), [](const FaceRecord& face) { return !face.slave; });
  return faces;
}

void add_face_records(const std::vector<std::vector<std::array<int, 9>>>& lists, bool slave,
                      const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                      std::vector<FaceRecord>& faces) {
  for (size_t k = 0; k < lists.size(); ++k)
    for (const auto& dofs : lists[k]) {
      const SubdomainInput& sub = local[k];
      FaceRecord face{global_ids[k], sub.body, dofs, {}, slave};
      for (size_t corner = 0; corner < 3; ++corner) {
        const auto d = static_cast<size_t>(dofs[3 * corner]);
        face.corners[corner] = {sub.x[d], sub.y[d], sub.z[d]};
      }
      faces.push_back(face);
    }
}

std::vector<double> pack(const std::vector<FaceRecord>& faces) {
  std::vector<double> packed;
  for (const FaceRecord& f : faces) {
    packed.insert(packed.end(), {double(f.subdomain), double(f.body)});
    for (int dof : f.dofs) packed.push_back(double(dof));
    for (const auto& corner : f.corners) packed.insert(packed.end(), corner.begin(), corner.end());
    packed.push_back(f.slave ? 1.0 : 0.0);
  }
  return packed;
}

std::vector<FaceRecord> unpack_faces(const std::vector<double>& packed) {
  std::vector<FaceRecord> faces;
  for (size_t k = 0; k + 21 <= packed.size(); k += 21) {
    FaceRecord f{static_cast<int>(packed[k]), static_cast<int>(packed[k + 1]), {}, {}, packed[k + 20] != 0};
    for (size_t i = 0; i < 9; ++i) f.dofs[i] = static_cast<int>(packed[k + 2 + i]);
    for (size_t c = 0; c < 3; ++c)
      for (size_t i = 0; i < 3; ++i) f.corners[c][i] = packed[k + 11 + 3 * c + i];
    faces.push_back(f);
  }
  return faces;
}

}  // namespace ffeti

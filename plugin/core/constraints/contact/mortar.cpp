#include "constraints/contact/mortar.h"

#include "constraints/constraint_rows.h"
#include "constraints/input_checks.h"
#include "constraints/surface_checks.h"
#include "constraints/contact/face_grid.h"
#include "constraints/contact/mortar_integration.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/obstacle.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace ffeti {
namespace {

using NodeKey = std::tuple<int, long long, long long, long long>;  // body, snapped position

/// One slave node's row in the making: int phi_j n.(u_m - u_s) <= int phi_j n.(x_s - x_m)
/// summed over the (slave face, master face) pairs, n each master face's normal.
struct MortarRow {
  std::map<std::pair<int, int>, double> coefficients;  ///< per (subdomain, dof)
  double gap = 0;
  double weight = 0;  ///< int phi_j over the covered part
  /// With friction: int phi_j (u_s - u_m) per (subdomain, dof), its component.
  std::map<std::pair<int, int>, std::pair<int, double>> jump;
  Point3 normal{0, 0, 0};  ///< the pairs' normals weighted by their int phi_j: the row's, unnormalized
};

/// (b - a) x (c - a): twice the area times the unit normal.
Point3 area_normal(const Triangle3& t) { return cross(minus(t[1], t[0]), minus(t[2], t[0])); }

double face_area(const Triangle3& t) {
  const Point3 n = area_normal(t);
  return std::sqrt(dot(n, n)) / 2;
}

Point3 unit_normal(const Triangle3& t) {
  const Point3 n = area_normal(t);
  const double length = std::sqrt(dot(n, n));
  return {n[0] / length, n[1] / length, n[2] / length};
}

bool by_identity(const FaceRecord& a, const FaceRecord& b) {
  return std::tie(a.subdomain, a.dofs) < std::tie(b.subdomain, b.dofs);
}

/// Adds one (slave face, master face) pair's integrals to the row of the slave's corner j.
/// `friction`: also the jump.
void add_pair(const FaceRecord& slave, const FaceRecord& master, const MortarIntegrals& in, size_t j, bool friction,
              MortarRow& row) {
  const Point3& n = in.normal;
  for (size_t k = 0; k < 3; ++k) {
    row.weight += in.D[j][k];
    for (size_t i = 0; i < 3; ++i) row.normal[i] += in.D[j][k] * n[i];
    for (size_t i = 0; i < 3; ++i) {
      row.coefficients[{slave.subdomain, slave.dofs[3 * k + i]}] -= in.D[j][k] * n[i];
      row.coefficients[{master.subdomain, master.dofs[3 * k + i]}] += in.M[j][k] * n[i];
      if (!friction) continue;
      auto& s = row.jump[{slave.subdomain, slave.dofs[3 * k + i]}];
      auto& m = row.jump[{master.subdomain, master.dofs[3 * k + i]}];
      s = {static_cast<int>(i), s.second + in.D[j][k]};
      m = {static_cast<int>(i), m.second - in.M[j][k]};
    }
  }
  row.gap += dot(n, in.G[j]);
}

/// The slave triangle scaled by 1 + 1e-4 about its centroid: its edges move out by far more
/// than the differences' step (1e-6 of the shortest edge), so a master it meets overlaps it
/// or may come to overlap it within that step.
Triangle3 enlarged(const Triangle3& t) {
  Triangle3 out = t;
  for (size_t d = 0; d < 3; ++d) {
    const double centre = (t[0][d] + t[1][d] + t[2][d]) / 3;
    for (Point3& p : out) p[d] = centre + (1 + 1e-4) * (p[d] - centre);
  }
  return out;
}

}  // namespace

const ListInput* Mortar::list_input() const {
  static const ListInput spec{"contactSlaveFaces", 9, "9 dofs per face (a_x, a_y, a_z, b_x, ..., c_z)"};
  return &spec;
}

void Mortar::read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                       ContactInput& contact) const {
  contact.input_of<MortarInput>().slave_faces = list_entries<9>(*list_input(), lists, ids);
}

void Mortar::check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                           const ContactInput& contact, int dimension) const {
  const auto& slave_faces = contact.input_of<MortarInput>().slave_faces;
  check_face_list(slave_faces, ids, subdomains, list_input()->argument);
  if (!any_entry(slave_faces)) return;
  // Its masters too (node to face checks their lists; a face with a dof outside its
  // subdomain is left to that check).
  const char* masters = contact_discretizations().at(static_cast<size_t>(ContactKind::node_to_face))->list_input()->argument;
  refuse_higher_order_faces(contact.input_of<NodeToFaceInput>().faces, ids, subdomains, masters);
  refuse_higher_order_faces(slave_faces, ids, subdomains, list_input()->argument);
  require(kind(), Feature::rows, dimension, list_input()->argument);
}

void Mortar::check_combination(const ContactInput& contact) const {
  if (list_given(contact) &&
      (any_entry(contact.slave_dofs) || contact.input_of<ObstacleInput>().given || contact.kind_parameters.count(ContactKind::ball)))
    throw InputError("contactSlaveFaces: the slave nodes of mortar contact are the corners of these faces; give "
                     "contactSlave (node to face, obstacle) or contactSlaveFaces (mortar), not both");
}

Point3 MortarGeometry::normal() const {
  const double length = std::sqrt(dot(weighted_normal, weighted_normal));
  return {weighted_normal[0] / length, weighted_normal[1] / length, weighted_normal[2] / length};
}

MortarGeometry::MortarGeometry(DofRef slave, const Point3& s, std::shared_ptr<const MortarSurface> surface,
                               std::vector<MortarPair> pairs, double snap, std::vector<JumpEntry> jump,
                               const Point3& weighted_normal)
    : ContactRowGeometry(ContactKind::mortar, slave, s, true),
      jump(std::move(jump)),
      weighted_normal(weighted_normal),
      surface_(std::move(surface)),
      pairs_(std::move(pairs)),
      length_(INFINITY) {
  std::map<DofRef, size_t> node_of;
  std::map<NodeKey, int> physical_of;
  const auto node = [&](const FaceRecord& f, size_t corner) {
    const DofRef x{f.subdomain, f.dofs[3 * corner]};
    const auto [it, added] = node_of.emplace(x, nodes_.size());
    if (added) {
      const Point3& p = f.corners[corner];
      const NodeKey key{f.body, std::llround(p[0] / snap), std::llround(p[1] / snap), std::llround(p[2] / snap)};
      physical_.push_back(physical_of.emplace(key, static_cast<int>(physical_of.size())).first->second);
      nodes_.push_back(x);
    }
    return it->second;
  };
  for (const MortarPair& pair : pairs_) {
    const FaceRecord &f = surface_->slaves[static_cast<size_t>(pair.slave)],
                     &m = surface_->masters[static_cast<size_t>(pair.master)];
    std::array<size_t, 6> corners{};
    for (size_t c = 0; c < 3; ++c) corners[c] = node(f, c);
    for (size_t c = 0; c < 3; ++c) corners[3 + c] = node(m, c);
    pair_nodes_.push_back(corners);
    for (const FaceRecord* face : {&f, &m})
      for (size_t c = 0; c < 3; ++c) {
        const Point3 edge = minus(face->corners[(c + 1) % 3], face->corners[c]);
        length_ = std::min(length_, std::sqrt(dot(edge, edge)));
      }
  }
}

RowAt MortarGeometry::row_at(const NodeMotion& v, double t) const {
  MortarRow row;
  for (size_t p = 0; p < pairs_.size(); ++p) {
    const MortarPair& pair = pairs_[p];
    const FaceRecord &f = surface_->slaves[static_cast<size_t>(pair.slave)],
                     &m = surface_->masters[static_cast<size_t>(pair.master)];
    Triangle3 slave_at, master_at;
    for (size_t c = 0; c < 3; ++c) {
      slave_at[c] = moved(f.corners[c], v[pair_nodes_[p][c]], t);
      master_at[c] = moved(m.corners[c], v[pair_nodes_[p][3 + c]], t);
    }
    // Every pair adds all its dofs, zero or not: the rows at t and -t list the same dofs.
    add_pair(f, m, integrate_mortar_pair(slave_at, master_at), static_cast<size_t>(pair.corner), false, row);
  }
  RowAt out;
  for (const auto& [dof, coefficient] : row.coefficients) {
    out.dofs.push_back({dof.first, dof.second});
    out.coefficients.push_back(coefficient / row.weight);
  }
  out.gap = row.gap / row.weight;  // without the node's gap (contactGap), which does not move
  return out;
}

std::string MortarGeometry::unverified_motion(const NodeMotion& v) const {
  const double step = difference_step(*this, v);
  if (step == 0) return "";
  const RowAt minus = row_at(v, -step), centre = row_at(v, 0), plus = row_at(v, step);
  // Second differences per physical node and component (the subdomains' copies of a node
  // share its force through the gluing rows, so a kink in how the copies split it is no
  // kink of the problem): ~step^2 where the row is smooth, ~step times the jump of the
  // slope at a kink.
  std::map<DofRef, std::pair<int, int>> node_component;  // dof -> (physical node, component)
  for (size_t p = 0; p < pairs_.size(); ++p) {
    const MortarPair& pair = pairs_[p];
    const FaceRecord* faces[2] = {&surface_->slaves[static_cast<size_t>(pair.slave)],
                                  &surface_->masters[static_cast<size_t>(pair.master)]};
    for (size_t side = 0; side < 2; ++side)
      for (size_t c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i)
          node_component[{faces[side]->subdomain, faces[side]->dofs[3 * c + static_cast<size_t>(i)]}] = {
              physical_[pair_nodes_[p][3 * side + c]], i};
  }
  std::map<std::pair<int, int>, double> second;
  for (size_t k = 0; k < centre.dofs.size(); ++k)
    second[node_component.at(centre.dofs[k])] += plus.coefficients[k] - 2 * centre.coefficients[k] + minus.coefficients[k];
  double worst = 0;
  for (const auto& entry : second) worst = std::max(worst, std::abs(entry.second));
  // Coefficients are of order 1 and the gap changes by the motion: a kink whose slope jumps
  // by 1 % of those scales is caught, a smooth row's 1e-12 is not. Scales are those of the
  // design's fastest node: a row moving by round-off only (its velocities ~1e-17 where the
  // field vanishes) changes the derivative by nothing, kink or not.
  const double speed = 1e-6 * length_ / step;
  const double kink = 1e-8 * std::max(1.0, v.reference_speed / speed);
  if (worst <= kink && std::abs(plus.gap - 2 * centre.gap + minus.gap) <= kink * length_) return "";
  return "the mortar row has a kink along this motion (one-sided derivatives differ: a slave face's edge lies on "
         "a master face's edge where the master surface bends or ends, and the motion moves it across): its "
         "derivative is not defined; move the faces along the edge or the surface without bending there, or mesh "
         "the slave and master sides so that their edges do not coincide";
}

std::vector<RowAt> MortarGeometry::slip_rows() const {
  const Point3 n = normal();
  std::vector<RowAt> rows;
  for (const Point3& t : tangent_pair(n)) {
    RowAt row{{}, {}, 0.0};
    for (const JumpEntry& e : jump) {
      row.dofs.push_back(e.dof);
      row.coefficients.push_back(t[static_cast<size_t>(e.component)] * e.coefficient);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

bool Mortar::selected(const ContactRecords& in) const {
  return std::any_of(in.faces.begin(), in.faces.end(), [](const FaceRecord& f) { return f.slave; });
}

void Mortar::add_rows(const ContactRecords& in, std::vector<Row>& rows) const {
  const std::vector<DofRecord>& records = in.records;
  const std::vector<FaceRecord>& faces = in.faces;
  const ContactInput& contact = in.contact;
  const double snap = in.snap;
  // Checked here, on the faces of all ranks: one rank may hold slave faces and no master face.
  if (std::all_of(faces.begin(), faces.end(), [](const FaceRecord& f) { return f.slave; }))
    throw InputError("contactSlaveFaces: mortar contact needs the master faces too (contactFaces=)");
  // Sorted, so that the sums and the rows do not depend on how faces are spread over ranks.
  const auto surface = std::make_shared<MortarSurface>();
  std::vector<FaceRecord>&slaves = surface->slaves, &masters = surface->masters;
  for (const FaceRecord& f : faces) (f.slave ? slaves : masters).push_back(f);
  std::sort(slaves.begin(), slaves.end(), by_identity);
  std::sort(masters.begin(), masters.end(), by_identity);
  const FaceGrid grid(masters);

  const std::vector<SlaveNode> nodes = slave_nodes(records, snap, 3);
  std::map<NodeKey, size_t> node_at;
  const auto key = [snap](int body, const Point3& p) {
    return NodeKey{body, std::llround(p[0] / snap), std::llround(p[1] / snap), std::llround(p[2] / snap)};
  };
  for (size_t j = 0; j < nodes.size(); ++j)
    node_at[key(nodes[j].x_dof->body, {nodes[j].x_dof->x, nodes[j].x_dof->y, nodes[j].x_dof->z})] = j;
  // Checked on all ranks' data: a slave node of contactSlave= on one rank beside slave faces
  // on another would get no row without a word.
  std::vector<char> is_corner(nodes.size(), 0);
  for (const FaceRecord& f : slaves)
    for (const Point3& p : f.corners) is_corner[node_at.at(key(f.body, p))] = 1;
  for (size_t j = 0; j < nodes.size(); ++j)
    if (!is_corner[j])
      throw InputError("contactSlave, contactSlaveFaces: the slave node at (" + std::to_string(nodes[j].x_dof->x) + ", " +
                       std::to_string(nodes[j].x_dof->y) + ", " + std::to_string(nodes[j].x_dof->z) +
                       ") is no corner of a slave face: mortar's slave nodes are those of contactSlaveFaces; give "
                       "one or the other on every rank");

  std::vector<MortarRow> pending(nodes.size());
  std::vector<std::vector<MortarPair>> pairs(nodes.size());  // per row, for its motion derivative
  std::vector<double> full_weight(nodes.size(), 0.0);  // int phi_j over all of its slave faces
  for (size_t slave_index = 0; slave_index < slaves.size(); ++slave_index) {
    const FaceRecord& f = slaves[slave_index];
    std::array<size_t, 3> corner_rows{};
    for (size_t c = 0; c < 3; ++c) corner_rows[c] = node_at.at(key(f.body, f.corners[c]));  // corners are slave dofs
    const Point3 n = unit_normal(f.corners);
    double longest = 0;
    Point3 centroid{};
    for (size_t c = 0; c < 3; ++c) {
      const Point3 &p = f.corners[c], &q = f.corners[(c + 1) % 3];
      longest = std::max(longest, std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]));
      for (size_t d = 0; d < 3; ++d) centroid[d] += p[d] / 3;
    }
    for (size_t c = 0; c < 3; ++c) full_weight[corner_rows[c]] += face_area(f.corners) / 3;
    // The face looks as far as the nearest master face of another body plus its longest
    // edge (the gap varies across a tilted face by less), within the search distance: a
    // master layer farther than that, a body beyond the one it touches, stays out of its
    // rows. Every direction, since the pairs are projected along the masters' normals.
    double nearest = 0;
    if (!grid.nearest(centroid, f.body, contact.search_distance, &nearest)) continue;
    const double reach = std::min(contact.search_distance, nearest + longest);
    Point3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const Point3& p : f.corners)
      for (size_t d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p[d] - reach), hi[d] = std::max(hi[d], p[d] + reach);
    grid.for_each_in_box(lo, hi, [&](const FaceRecord& m) {
      if (m.body == f.body || dot(unit_normal(m.corners), n) >= 0) return;  // only masters facing the slave
      const MortarIntegrals in = integrate_mortar_pair(f.corners, m.corners);
      // A pair that only touches (a shared edge or corner) adds nothing, but a motion may
      // make it overlap: the rows' derivatives keep it.
      const bool overlaps = in.area > 0;
      const MortarIntegrals near = overlaps ? in : integrate_mortar_pair(enlarged(f.corners), m.corners);
      if (!(near.area > 0)) return;
      double gap = 0;
      for (const Point3& g : near.G) gap += dot(near.normal, g);
      if (std::abs(gap / near.area) > reach) return;  // its mean normal gap
      const int master_index = static_cast<int>(&m - masters.data());
      for (size_t j = 0; j < 3; ++j) {
        pairs[corner_rows[j]].push_back({static_cast<int>(slave_index), master_index, static_cast<int>(j)});
        if (overlaps) add_pair(f, m, in, j, contact.has_friction(), pending[corner_rows[j]]);
      }
    });
  }

  for (size_t j = 0; j < nodes.size(); ++j) {
    const MortarRow& pending_row = pending[j];
    // No master covers its faces (or a sliver far from the node, whose row would nearly
    // repeat its neighbours'): no contact possible here.
    if (!(pending_row.weight > 1e-3 * full_weight[j])) continue;
    const SlaveNode& node = nodes[j];
    std::vector<JumpEntry> jump;  // divided by int phi_j like the row
    for (const auto& [dof, share] : pending_row.jump)
      if (share.second != 0) jump.push_back({{dof.first, dof.second}, share.first, share.second / pending_row.weight});
    const auto geometry = std::make_shared<const MortarGeometry>(
        DofRef{node.x_dof->subdomain, node.x_dof->dof}, Point3{node.x_dof->x, node.x_dof->y, node.x_dof->z}, surface,
        std::move(pairs[j]), snap, std::move(jump), pending_row.normal);
    // Divided by int phi_j, so that the multiplier is a force like the other rows'.
    Row row{{}, pending_row.gap / pending_row.weight + node.x_dof->gap, RowKind::contact, false, geometry,
            -1, node.x_dof->law_value};
    for (const auto& [dof, coefficient] : pending_row.coefficients)
      if (coefficient != 0) row.entries.push_back({dof.first, dof.second, coefficient / pending_row.weight});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti

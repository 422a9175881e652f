#include "constraints/input_checks.h"

#include "constraints/capabilities.h"
#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/obstacle.h"
#include "constraints/surface_checks.h"

#include "base/errors.h"
#include "base/parallel_for.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <unordered_set>

namespace ffeti {
namespace {

/// The smallest positive Coulomb coefficient accepted (input checks below).
constexpr double kSmallestFriction = 1e-6;

std::string indexed(const char* name, size_t s) { return std::string(name) + "[" + std::to_string(s) + "]"; }

void check_stiffness(const SparseMatrix& K, const std::string& name) {
  if (K.rows() == 0) throw InputError(name + ": empty matrix");
  if (K.rows() != K.cols())
    throw InputError(name + ": not square (" + std::to_string(K.rows()) + " x " +
                     std::to_string(K.cols()) + ")");
  if (!K.isCompressed()) {  // the walk below reads compressed columns
    SparseMatrix compressed = K;
    compressed.makeCompressed();
    return check_stiffness(compressed, name);
  }
  const double scale = K.coeffs().size() ? K.coeffs().cwiseAbs().maxCoeff() : 0.0;
  if (!std::isfinite(scale)) throw InputError(name + ": has a non-finite entry (nan or inf)");
  // Each entry against its mirror in one pass over K (no transposed copy, no search): the
  // columns are walked in order, so the mirrors of column j's entries below the diagonal,
  // (j, i) in column i, come up in ascending row order there; a cursor per column follows
  // them. An entry a cursor steps over, or never reaches, has no stored mirror (0).
  const auto asymmetric = [&](int i, int j, double value, double mirror) {
    const double difference = mirror - value;
    if (std::abs(difference) <= 1e-10 * scale) return;
    throw InputError(name + ": not symmetric: K(" + std::to_string(i) + "," + std::to_string(j) + ") and K(" +
                     std::to_string(j) + "," + std::to_string(i) + ") differ by " + std::to_string(difference) +
                     " (assemble a symmetric bilinear form; Dirichlet by tgv=-1 breaks "
                     "symmetry, pass the dofs as Dirichlet data instead)");
  };
  const int* start = K.outerIndexPtr();
  const int* row = K.innerIndexPtr();
  const double* value = K.valuePtr();
  std::vector<int> cursor(start, start + K.outerSize());  // next entry above the diagonal, per column
  for (int j = 0; j < K.outerSize(); ++j)
    for (int p = start[j]; p < start[j + 1]; ++p) {
      const int i = row[p];
      if (i <= j) continue;
      int& q = cursor[static_cast<size_t>(i)];  // column i, looking for row j
      for (; q < start[i + 1] && row[q] < j; ++q) asymmetric(row[q], i, value[q], 0.0);
      const bool stored = q < start[i + 1] && row[q] == j;
      asymmetric(i, j, value[p], stored ? value[q] : 0.0);
      if (stored) ++q;
    }
  for (int i = 0; i < K.outerSize(); ++i)  // above-diagonal entries no lower entry claimed
    for (int q = cursor[static_cast<size_t>(i)]; q < start[i + 1] && row[q] < i; ++q) asymmetric(row[q], i, value[q], 0.0);
  for (Eigen::Index i = 0; i < K.rows(); ++i)
    if (!(K.coeff(i, i) > 0))
      throw InputError(name + ": diagonal entry " + std::to_string(i) + " is " +
                       std::to_string(K.coeff(i, i)) + ", a stiffness matrix needs > 0");
}

void check_dofs(const std::vector<int>& dofs, Eigen::Index n, const std::string& name) {
  for (int dof : dofs)
    if (dof < 0 || dof >= n)
      throw InputError(name + ": dof " + std::to_string(dof) + " is outside 0.." +
                       std::to_string(n - 1));
}

/// Contact triangles (9 dofs each, indices already checked): each corner's three dofs are
/// its x, y and z (component 0, 1, 2) at one node, and the corners are distinct nodes. Rows
/// built from a face listed otherwise would push along the wrong axes without a word.
void check_face_corners(const std::vector<std::vector<std::array<int, 9>>>& faces, const std::vector<size_t>& ids,
                        const std::vector<SubdomainInput>& subdomains, const char* name) {
  for (size_t k = 0; k < faces.size(); ++k) {
    const SubdomainInput& sub = subdomains[k];
    if (sub.z.empty()) continue;  // refused elsewhere: faces need Z
    for (size_t f = 0; f < faces[k].size(); ++f) {
      const auto& dofs = faces[k][f];
      const auto at = [&](int corner, int i) { return static_cast<size_t>(dofs[static_cast<size_t>(3 * corner + i)]); };
      const auto where = [&] { return indexed(name, ids[k]) + ": face " + std::to_string(f) + " "; };
      for (int corner = 0; corner < 3; ++corner)
        for (int i = 0; i < 3; ++i) {
          if (!sub.component.empty() && sub.component[at(corner, i)] != i)
            throw InputError(where() + "lists dof " + std::to_string(at(corner, i)) + " as its corner " +
                             std::to_string(corner) + "'s component " + std::to_string(i) + ", but it is component " +
                             std::to_string(sub.component[at(corner, i)]) + " (list x, y, z of each corner)");
          if (sub.x[at(corner, i)] != sub.x[at(corner, 0)] || sub.y[at(corner, i)] != sub.y[at(corner, 0)] ||
              sub.z[at(corner, i)] != sub.z[at(corner, 0)])
            throw InputError(where() + "corner " + std::to_string(corner) + ": its dofs lie at different nodes");
        }
      for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
          if (sub.x[at(a, 0)] == sub.x[at(b, 0)] && sub.y[at(a, 0)] == sub.y[at(b, 0)] && sub.z[at(a, 0)] == sub.z[at(b, 0)])
            throw InputError(where() + "has two corners at one node (no area)");
      const std::array<double, 3> u{sub.x[at(1, 0)] - sub.x[at(0, 0)], sub.y[at(1, 0)] - sub.y[at(0, 0)],
                                    sub.z[at(1, 0)] - sub.z[at(0, 0)]};
      const std::array<double, 3> v{sub.x[at(2, 0)] - sub.x[at(0, 0)], sub.y[at(2, 0)] - sub.y[at(0, 0)],
                                    sub.z[at(2, 0)] - sub.z[at(0, 0)]};
      const double cross = std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
      if (!(cross > 1e-12 * std::hypot(u[0], u[1], u[2]) * std::hypot(v[0], v[1], v[2])))
        throw InputError(where() + "has collinear corners (no area, no normal)");
    }
  }
}

}  // namespace

void check_list_dofs(const std::vector<std::vector<int>>& lists, const std::vector<size_t>& ids,
                     const std::vector<SubdomainInput>& subdomains, const char* name) {
  if (!lists.empty() && lists.size() != subdomains.size())
    throw InputError(std::string(name) + ": has " + std::to_string(lists.size()) +
                     " entries for " + std::to_string(subdomains.size()) + " subdomains");
  for (size_t k = 0; k < lists.size(); ++k) check_dofs(lists[k], subdomains[k].K.rows(), indexed(name, ids[k]));
}

void check_face_list(const std::vector<std::vector<std::array<int, 9>>>& faces, const std::vector<size_t>& ids,
                     const std::vector<SubdomainInput>& subdomains, const char* name) {
  check_entry_dofs(faces, ids, subdomains, name);
  check_face_corners(faces, ids, subdomains, name);
  check_face_orientation(faces, ids, subdomains, name);
}

namespace {

/// A field of one value per dof and subdomain (empty entries allowed), each finite and at
/// least `lowest`.
void check_dof_field(const std::vector<std::vector<double>>& field, const std::vector<size_t>& ids,
                     const std::vector<SubdomainInput>& subdomains, const char* name, double lowest) {
  if (!field.empty() && field.size() != subdomains.size())
    throw InputError(std::string(name) + ": has " + std::to_string(field.size()) + " entries for " +
                     std::to_string(subdomains.size()) + " subdomains");
  for (size_t k = 0; k < field.size(); ++k) {
    const std::vector<double>& values = field[k];
    if (!values.empty() && values.size() != static_cast<size_t>(subdomains[k].K.rows()))
      throw InputError(indexed(name, ids[k]) + ": needs one value per dof (" + std::to_string(subdomains[k].K.rows()) +
                       ") or none, got " + std::to_string(values.size()));
    for (size_t i = 0; i < values.size(); ++i)
      if (!(std::isfinite(values[i]) && values[i] >= lowest))
        throw InputError(indexed(name, ids[k]) + ": entry " + std::to_string(i) + " is " + std::to_string(values[i]) +
                         (lowest > -INFINITY ? ", it must be a finite number >= " + std::to_string(lowest)
                                             : ", it must be a finite number"));
  }
}

/// One subdomain's own data: K (unless `check_K` is false: a matrix shared with a subdomain
/// checked before), F, coordinates, body, components and Dirichlet lists; `first` (named
/// `first_id`) is the subdomain whose dimension every other must share.
void check_subdomain(const SubdomainInput& sub, size_t s, bool check_K, const SubdomainInput& first, size_t first_id) {
  const std::string K_name = sub.K.name().empty() ? indexed("K", s) : sub.K.name();
  if (check_K) check_stiffness(sub.K, K_name);
  const auto n = static_cast<size_t>(sub.K.rows());
  if (static_cast<size_t>(sub.f.size()) != n)
    throw InputError(indexed("F", s) + ": has " + std::to_string(sub.f.size()) + " entries, " + K_name + " has " +
                     std::to_string(n) + " rows");
  if (!sub.f.allFinite()) throw InputError(indexed("F", s) + ": has a non-finite entry");
  if (sub.x.size() != n || sub.y.size() != n)
    throw InputError(indexed("X", s) + ", " + indexed("Y", s) + ": need one coordinate per dof (" +
                     std::to_string(n) + "), got " + std::to_string(sub.x.size()) + " and " +
                     std::to_string(sub.y.size()));
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(sub.x[i]) || !std::isfinite(sub.y[i]))
      throw InputError(indexed("X", s) + ", " + indexed("Y", s) + ": the coordinates of dof " + std::to_string(i) +
                       " are not finite (" + std::to_string(sub.x[i]) + ", " + std::to_string(sub.y[i]) + ")");
  if (!sub.z.empty() && sub.z.size() != n)
    throw InputError(indexed("Z", s) + ": needs one coordinate per dof (" + std::to_string(n) + "), got " +
                     std::to_string(sub.z.size()));
  for (size_t i = 0; i < sub.z.size(); ++i)
    if (!std::isfinite(sub.z[i]))
      throw InputError(indexed("Z", s) + ": the coordinate of dof " + std::to_string(i) + " is not finite");
  if (sub.z.empty() != first.z.empty())
    throw InputError(indexed("Z", s) + ": " + (sub.z.empty() ? "missing" : "given") + " where Z[" +
                     std::to_string(first_id) + "] is " + (sub.z.empty() ? "given" : "missing") +
                     ": every subdomain of a problem is plane or every one has a third coordinate");
  if (sub.body < 0)
    throw InputError(indexed("body", s) + ": is " + std::to_string(sub.body) + ", body numbers must be >= 0");
  if (!sub.component.empty() && sub.component.size() != n)
    throw InputError(indexed("component", s) + ": needs one entry per dof");
  const int components = sub.z.empty() ? 2 : 3;
  for (int c : sub.component)
    if (c < 0 || c >= components)
      throw InputError(indexed("component", s) + ": components must be 0 or 1" + (sub.z.empty() ? "" : " or 2") +
                       ", got " + std::to_string(c));
  check_dofs(sub.dirichlet_dofs, sub.K.rows(), indexed("dirichlet", s));
  if (!sub.dirichlet_values.empty() && sub.dirichlet_values.size() != sub.dirichlet_dofs.size())
    throw InputError(indexed("dirichletValues", s) + ": needs one value per Dirichlet dof");
  for (size_t i = 0; i < sub.dirichlet_values.size(); ++i)
    if (!std::isfinite(sub.dirichlet_values[i]))
      throw InputError(indexed("dirichletValues", s) + ": entry " + std::to_string(i) + " is not finite");
}

/// The input of the kinds that own theirs (ContactInput::kind_parameters), each checked by
/// its unit. Such a kind takes the slave nodes of contactSlave: another kind for them is
/// refused, naming both arguments.
void check_kind_inputs(const ContactInput& contact, int dimension) {
  const auto& units = contact_discretizations();
  for (const auto& [kind, values] : contact.kind_parameters) {
    const ContactDiscretization& unit = *units.at(static_cast<size_t>(kind));
    if (!unit.input()) throw InputError(std::string(unit.capabilities().name) + " contact takes no parameters");
    unit.check_input(values, dimension);
    const auto list = std::find_if(units.begin(), units.end(), [&](const auto& u) { return u->list_given(contact); });
    const char* other = contact.input_of<ObstacleInput>().given ? "obstacle"
                        : list != units.end() ? (*list)->list_input()->argument
                        : contact.kind_parameters.size() > 1
                            ? units.at(static_cast<size_t>(contact.kind_parameters.begin()->first))->input()->argument
                            : nullptr;
    if (other && other != unit.input()->argument)
      throw InputError(std::string(unit.input()->argument) + ", " + other +
                       ": the slave nodes of contactSlave take one kind of contact; give one");
  }
}

/// Local subdomain k's name in messages: global_ids[k], or k itself.
std::vector<size_t> message_ids(size_t count, const std::vector<int>& global_ids) {
  std::vector<size_t> ids;
  for (size_t k = 0; k < count; ++k) ids.push_back(global_ids.empty() ? k : static_cast<size_t>(global_ids[k]));
  return ids;
}

}  // namespace

void validate_contact_gaps(const std::vector<std::vector<double>>& gaps, const std::vector<SubdomainInput>& subdomains,
                           const std::vector<int>& global_ids) {
  check_dof_field(gaps, message_ids(subdomains.size(), global_ids), subdomains, "contactGap", -INFINITY);
}

void validate_input(const std::vector<SubdomainInput>& subdomains, const ContactInput& contact,
                    const std::vector<int>& global_ids) {
  const std::vector<size_t> ids = message_ids(subdomains.size(), global_ids);
  // Thousands of subdomains check on the set-up's threads (the symmetry test reads every
  // entry of every K, once per matrix where subdomains share one); the error named is the
  // lowest subdomain's, as in a serial loop.
  std::vector<char> checks_K(subdomains.size(), 1);
  std::unordered_set<const SparseMatrix*> seen;
  for (size_t k = 0; k < subdomains.size(); ++k) checks_K[k] = seen.insert(&subdomains[k].K.get()).second;
  parallel_for_each(static_cast<int>(subdomains.size()), 0, [&](int k) {
    const auto at = static_cast<size_t>(k);
    check_subdomain(subdomains[at], ids[at], checks_K[at] != 0, subdomains.front(), ids.front());
  });
  // contact.three_d: set by a parallel set-up for a rank that may hold no subdomain.
  const bool three_d = contact.three_d || (!subdomains.empty() && !subdomains.front().z.empty());
  const int dimension = three_d ? 3 : 2;
  check_list_dofs(contact.slave_dofs, ids, subdomains, "contactSlave");
  // Each kind's own input against the subdomains (its lists), then its rule against the
  // other kinds' input (which kind the arguments choose).
  for (const auto& unit : contact_discretizations()) unit->check_against(subdomains, ids, contact, dimension);
  for (const auto& unit : contact_discretizations()) unit->check_combination(contact);
  if (!(contact.search_distance > 0)) throw InputError("contactRadius: must be > 0");
  validate_contact_gaps(contact.gap_field, subdomains, global_ids);
  for (const auto& [name, value] : {std::pair<const char*, double>{"friction", contact.friction},
                                    std::pair<const char*, double>{"slipBound", contact.slip_bound}})
    if (!std::isfinite(value) || (value < 0 && value != -1))
      throw InputError(std::string(name) + ": must be a finite number >= 0, got " + std::to_string(value));
  check_dof_field(contact.friction_field, ids, subdomains, "frictionField", 0.0);
  // Coulomb coefficients in (0, 1e-6) bound friction forces below what the solver's
  // tolerance resolves against the normal forces: mu = 1e-9 and 1e-300 ran to maxit on the
  // 3D block (the disc bounds a round-off apart), and a body held by them has no defined
  // tangential position. 0 is frictionless contact.
  const auto refuse_tiny = [](const std::string& name, double mu) {
    if (mu > 0 && mu < kSmallestFriction)
      throw InputError(name + ": " + (std::ostringstream() << mu).str() + " lies between 0 and 1e-6: a coefficient that small holds "
                       "friction forces below what the solver resolves against the normal forces; give 0 for "
                       "frictionless contact, or at least 1e-6");
  };
  refuse_tiny("friction", contact.friction);
  for (size_t k = 0; k < contact.friction_field.size(); ++k)
    for (size_t i = 0; i < contact.friction_field[k].size(); ++i)
      refuse_tiny(indexed("frictionField", ids[k]) + ": entry " + std::to_string(i), contact.friction_field[k][i]);
  if (!contact.friction_field.empty() && contact.friction < 0 && contact.slip_bound < 0)
    throw InputError("frictionField: needs friction >= 0 as well (its value where the field has no entry; "
                     "fetiSetup sets 0 when only frictionField is given)");
  if (!contact.friction_field.empty() && contact.slip_bound >= 0)
    throw InputError("frictionField, slipBound: a coefficient per row is Coulomb's law; Tresca's bound per row is slipBoundField");
  check_dof_field(contact.slip_bound_field, ids, subdomains, "slipBoundField", 0.0);
  if (!contact.slip_bound_field.empty() && contact.slip_bound < 0)
    throw InputError("slipBoundField: needs slipBound >= 0 as well (its value where the field has no entry; "
                     "fetiSetup sets 0 when only slipBoundField is given)");
  if (!contact.slip_bound_field.empty() && !contact.friction_field.empty())
    throw InputError("frictionField, slipBoundField: give one law, Coulomb (frictionField=) or Tresca (slipBoundField=)");
  if (contact.friction >= 0 && contact.slip_bound >= 0)
    throw InputError("friction, slipBound: give one law, Coulomb (friction=) or Tresca (slipBound=), not both");
  check_kind_inputs(contact, dimension);

}

}  // namespace ffeti

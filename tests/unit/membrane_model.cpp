#include "membrane_model.h"
#include "constraints/contact/node_to_node.h"

#include <Eigen/SparseLU>

#include <cmath>
#include <map>
#include <set>

namespace ffeti::test {

DualSolveSettings tight() {
  DualSolveSettings settings;
  settings.tolerance = 1e-12;
  settings.max_hessian = 100000;
  return settings;
}

SubdomainInput p1_rectangle(double x0, double y0, double w, double h, int nx, int ny,
                            double factor, const std::function<double(double, double)>& f,
                            int body, const std::function<double(double)>& x_map) {
  SubdomainInput s;
  s.body = body;
  const int n = (nx + 1) * (ny + 1);
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = x0 + w * i / nx;
      s.x.push_back(x_map ? x_map(x) : x);
      s.y.push_back(y0 + h * j / ny);
    }
  s.f = Vec::Zero(n);
  std::vector<Eigen::Triplet<double, int>> entries;
  auto add_triangle = [&](int a, int b, int c) {
    const int v[3] = {a, b, c};
    const double ax = s.x[a], ay = s.y[a];
    const double area = 0.5 * ((s.x[b] - ax) * (s.y[c] - ay) - (s.x[c] - ax) * (s.y[b] - ay));
    double gx[3], gy[3];
    for (int k = 0; k < 3; ++k) {  // gradient of the barycentric coordinate of vertex k
      const int p = v[(k + 1) % 3], q = v[(k + 2) % 3];
      gx[k] = (s.y[p] - s.y[q]) / (2 * area);
      gy[k] = (s.x[q] - s.x[p]) / (2 * area);
    }
    const double cx = (s.x[a] + s.x[b] + s.x[c]) / 3, cy = (s.y[a] + s.y[b] + s.y[c]) / 3;
    const double load = f(cx, cy) * std::abs(area) / 3;
    for (int k = 0; k < 3; ++k) {
      s.f[v[k]] += load;
      for (int l = 0; l < 3; ++l)
        entries.emplace_back(v[k], v[l], factor * std::abs(area) * (gx[k] * gx[l] + gy[k] * gy[l]));
    }
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      add_triangle(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      add_triangle(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  s.K.edit().resize(n, n);
  s.K.edit().setFromTriplets(entries.begin(), entries.end());
  s.K.edit().makeCompressed();
  return s;
}

SubdomainInput two_components(const SubdomainInput& scalar) {
  const auto n = static_cast<int>(scalar.K.rows());
  SubdomainInput v;
  v.body = scalar.body;
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int j = 0; j < n; ++j)
    for (SparseMatrix::InnerIterator it(scalar.K, j); it; ++it)
      for (int c = 0; c < 2; ++c) entries.emplace_back(2 * it.row() + c, 2 * j + c, it.value());
  v.K.edit().resize(2 * n, 2 * n);
  v.K.edit().setFromTriplets(entries.begin(), entries.end());
  v.f = Vec::Zero(2 * n);
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 2; ++c) v.x.push_back(scalar.x[k]), v.y.push_back(scalar.y[k]), v.component.push_back(c);
  return v;
}

MembraneOptions membrane_options(int n, int N) {
  MembraneOptions o;
  o.n = n;
  o.N = N;
  return o;
}

std::function<double(double)> graded_towards_contact(int n, double ratio) {
  const double a = std::log(ratio) * n / (n - 1.0);  // n - 1 cell widths between the first and last
  return [a](double x) { return 1.0 - (std::exp(a * (1.0 - x)) - 1.0) / (std::exp(a) - 1.0); };
}

std::vector<SubdomainInput> membrane_subdomains(const MembraneOptions& o) {
  const auto load = [](double x, double y) {
    if (x < 1) return y > 0.75 ? -3.0 : 0.0;
    return y < 0.25 ? -1.0 : 0.0;
  };
  const int m = o.n / o.N;  // cells per subdomain side
  const double H = 1.0 / o.N;
  std::vector<SubdomainInput> subs;
  for (int body = 0; body < (o.body2 ? 2 : 1); ++body)
    for (int J = 0; J < o.N; ++J)
      for (int I = 0; I < o.N; ++I) {
        SubdomainInput s = p1_rectangle(body + I * H, J * H, H, H, m, m, 2.0, load, body,
                                        body == 0 ? o.x_map : std::function<double(double)>{});
        for (int k = 0; k < static_cast<int>(s.x.size()); ++k) {
          const bool left = body == 0 && s.x[k] == 0.0;
          const bool right = body == 1 && o.fix_right_body && std::abs(s.x[k] - 2.0) < 1e-12;
          if (left || right) s.dirichlet_dofs.push_back(k);
        }
        subs.push_back(std::move(s));
      }
  return subs;
}

ContactInput membrane_contact(const std::vector<SubdomainInput>& subs) {
  ContactInput contact;
  contact.slave_dofs.resize(subs.size());
  contact.input_of<NodeToNodeInput>().masters.resize(subs.size());
  for (size_t s = 0; s < subs.size(); ++s)
    for (int k = 0; k < static_cast<int>(subs[s].x.size()); ++k)
      if (std::abs(subs[s].x[k] - 1.0) < 1e-12)
        (subs[s].body == 0 ? contact.slave_dofs : contact.input_of<NodeToNodeInput>().masters)[s].push_back(k);
  return contact;
}

ReferenceSolution membrane_reference(int n) {
  const std::vector<SubdomainInput> bodies = membrane_subdomains(membrane_options(n, 1));  // one subdomain each
  const int n0 = static_cast<int>(bodies[0].K.rows()), n1 = static_cast<int>(bodies[1].K.rows());
  // Unknowns: body 0 without its Dirichlet dofs, then body 1.
  std::vector<int> index0(n0, -1);
  int free0 = 0;
  std::set<int> fixed(bodies[0].dirichlet_dofs.begin(), bodies[0].dirichlet_dofs.end());
  for (int k = 0; k < n0; ++k)
    if (!fixed.count(k)) index0[k] = free0++;
  const int nu = free0 + n1;
  std::vector<Eigen::Triplet<double, int>> K_entries;
  Vec f = Vec::Zero(nu);
  for (int j = 0; j < n0; ++j)
    for (SparseMatrix::InnerIterator it(bodies[0].K, j); it; ++it)
      if (index0[it.row()] >= 0 && index0[j] >= 0) K_entries.emplace_back(index0[it.row()], index0[j], it.value());
  for (int k = 0; k < n0; ++k)
    if (index0[k] >= 0) f[index0[k]] = bodies[0].f[k];
  for (int j = 0; j < n1; ++j)
    for (SparseMatrix::InnerIterator it(bodies[1].K, j); it; ++it)
      K_entries.emplace_back(free0 + it.row(), free0 + j, it.value());
  f.tail(n1) = bodies[1].f;
  // Contact pairs u0(1,y) - u1(1,y) <= 0, by y.
  std::map<long, std::pair<int, int>> pairs;
  for (int k = 0; k < n0; ++k)
    if (std::abs(bodies[0].x[k] - 1) < 1e-12) pairs[std::lround(bodies[0].y[k] * n)].first = index0[k];
  for (int k = 0; k < n1; ++k)
    if (std::abs(bodies[1].x[k] - 1) < 1e-12) pairs[std::lround(bodies[1].y[k] * n)].second = free0 + k;
  std::vector<std::pair<int, int>> rows;
  for (const auto& [key, p] : pairs) rows.push_back(p);
  const int q = static_cast<int>(rows.size());

  std::vector<char> active(q, 1);
  Vec u, lambda;
  ReferenceSolution reference{0, {}, 0};
  for (int iteration = 0; iteration < 100; ++iteration) {
    // [K B_A'; B_A 0] [u; lambda] = [f; 0], inactive multipliers pinned to 0 by unit rows.
    std::vector<Eigen::Triplet<double, int>> entries = K_entries;
    for (int i = 0; i < q; ++i) {
      if (active[i]) {
        entries.emplace_back(nu + i, rows[i].first, 1.0), entries.emplace_back(nu + i, rows[i].second, -1.0);
        entries.emplace_back(rows[i].first, nu + i, 1.0), entries.emplace_back(rows[i].second, nu + i, -1.0);
      } else {
        entries.emplace_back(nu + i, nu + i, 1.0);
      }
    }
    SparseMatrix M(nu + q, nu + q);
    M.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<SparseMatrix> lu(M);
    Vec rhs = Vec::Zero(nu + q);
    rhs.head(nu) = f;
    const Vec z = lu.solve(rhs);
    u = z.head(nu);
    lambda = z.tail(q);
    std::vector<char> next(q);
    for (int i = 0; i < q; ++i) next[i] = lambda[i] + (u[rows[i].first] - u[rows[i].second]) * n > 0;
    reference.iterations = iteration + 1;
    if (next == active) break;
    active = next;
  }
  SparseMatrix K(nu, nu);
  K.setFromTriplets(K_entries.begin(), K_entries.end());
  reference.energy = 0.5 * u.dot(K * u) - f.dot(u);
  for (auto it = pairs.begin(); it != pairs.end(); ++it) {
    const int i = static_cast<int>(std::distance(pairs.begin(), it));
    if (active[i] && lambda[i] > 0) reference.active_y.push_back(double(it->first) / n);
  }
  return reference;
}

FetiProblem membrane_problem(const MembraneOptions& o, FetiVariant variant, int threads,
                             DualPreconditioner preconditioner, InterfaceScaling scaling) {
  auto subs = membrane_subdomains(o);
  ContactInput contact = o.with_contact ? membrane_contact(subs) : ContactInput{};
  FetiSetupSettings setup;
  setup.variant = variant;
  setup.threads = threads;
  setup.preconditioner = preconditioner;
  setup.scaling = scaling;
  return FetiProblem(std::move(subs), contact, setup);
}

}  // namespace ffeti::test

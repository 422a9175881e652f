#include "native/problem_file.h"

#include "feti/errors.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>

namespace ffeti::native {
namespace {

using nlohmann::json;

/// One JSON object of the problem file read key by key: every error names the file and
/// the key's path ("subdomains[2].matrix"), and keys nobody asked for are refused, so that
/// a misspelt option is an error, not a silently ignored default.
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string file, std::string where)
      : object_(object), file_(std::move(file)), where_(std::move(where)) {
    if (!object_.is_object()) fail(where_.empty() ? "the file" : where_, "must be a JSON object");
  }

  template <class T>
  T required(const std::string& key) {
    if (!object_.contains(key)) fail(path(key), "missing");
    return get<T>(key);
  }

  template <class T>
  T optional(const std::string& key, T fallback) {
    return object_.contains(key) ? get<T>(key) : fallback;
  }

  bool has(const std::string& key) {
    known_.insert(key);
    return object_.contains(key);
  }

  const json& child(const std::string& key) {
    known_.insert(key);
    return object_.at(key);
  }

  std::string path(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }
  const std::string& file() const { return file_; }

  /// Call after reading: refuses keys this reader did not ask for.
  void finish() const {
    for (const auto& [key, value] : object_.items())
      if (!known_.count(key)) fail(path(key), "unknown key");
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_ + ": " + key + ": " + what);
  }

 private:
  template <class T>
  T get(const std::string& key) {
    known_.insert(key);
    try {
      return object_.at(key).get<T>();
    } catch (const json::exception&) {
      fail(path(key), std::string("must be ") + type_name<T>() + ", got " + object_.at(key).dump());
    }
  }

  template <class T>
  static const char* type_name() {
    if constexpr (std::is_same_v<T, std::string>) return "a string";
    else if constexpr (std::is_same_v<T, bool>) return "true or false";
    else if constexpr (std::is_integral_v<T>) return "an integer";
    else if constexpr (std::is_floating_point_v<T>) return "a number";
    else return "a list of integers";
  }

  const json& object_;
  std::string file_, where_;
  std::set<std::string> known_;
};

/// The entries of the list `key` (required), each read by `read_one(reader)`.
template <class T, class Read>
std::vector<T> read_list(ObjectReader& parent, const std::string& key, bool required, Read read_one) {
  std::vector<T> items;
  if (!parent.has(key)) {
    if (required) parent.fail(parent.path(key), "missing");
    return items;
  }
  const json& list = parent.child(key);
  if (!list.is_array()) parent.fail(parent.path(key), "must be a list");
  for (size_t i = 0; i < list.size(); ++i) {
    ObjectReader reader(list[i], parent.file(), parent.path(key) + "[" + std::to_string(i) + "]");
    items.push_back(read_one(reader));
    reader.finish();
  }
  return items;
}

std::array<double, 2> pair_of_numbers(ObjectReader& reader, const std::string& key) {
  const auto values = reader.required<std::vector<double>>(key);
  if (values.size() != 2) reader.fail(reader.path(key), "needs two numbers [x, y]");
  return {values[0], values[1]};
}

DofMapSpec read_dof_map(ObjectReader& r) {
  DofMapSpec dofs;
  dofs.getdp_pre = r.optional<std::string>("getdp", "");
  dofs.system = r.optional<int>("system", 0);
  dofs.explicit_file = r.optional<std::string>("file", "");
  if (dofs.getdp_pre.empty() == dofs.explicit_file.empty())
    r.fail(r.path("getdp"), "give either \"getdp\" (a .pre file, with \"system\") or \"file\" (node and component per row)");
  if (dofs.system < 0) r.fail(r.path("system"), "must be >= 0");
  return dofs;
}

SubdomainSpec read_subdomain(ObjectReader& r, int body_count) {
  SubdomainSpec sub;
  sub.surfaces = r.required<std::vector<int>>("surfaces");
  if (sub.surfaces.empty()) r.fail(r.path("surfaces"), "needs at least one physical surface");
  sub.partition = r.optional<int>("partition", 0);
  if (sub.partition < 0) r.fail(r.path("partition"), "must be >= 1 (0 or absent: every partition)");
  sub.body = r.optional<int>("body", 0);
  if (sub.body < 0 || sub.body >= body_count)
    r.fail(r.path("body"), "must lie in [0, " + std::to_string(body_count) + "): the index of one of \"bodies\"");
  sub.matrix = r.required<std::string>("matrix");
  sub.rhs = r.required<std::string>("rhs");
  if (!r.has("dofs")) r.fail(r.path("dofs"), "missing");
  ObjectReader dofs(r.child("dofs"), r.file(), r.path("dofs"));
  sub.dofs = read_dof_map(dofs);
  dofs.finish();
  return sub;
}

BodySpec read_body(ObjectReader& r) {
  BodySpec body;
  body.name = r.optional<std::string>("name", "");
  if (r.has("material")) {
    ObjectReader m(r.child("material"), r.file(), r.path("material"));
    MaterialSpec material;
    material.young = m.required<double>("E");
    material.poisson = m.required<double>("nu");
    const std::string model = m.optional<std::string>("model", "plane strain");
    if (model != "plane strain" && model != "plane stress")
      m.fail(m.path("model"), "\"" + model + "\" is not one of \"plane strain\", \"plane stress\"");
    material.plane_stress = model == "plane stress";
    if (!(material.young > 0)) m.fail(m.path("E"), "must be > 0");
    if (!(material.poisson >= 0 && material.poisson < 0.5)) m.fail(m.path("nu"), "must lie in [0, 0.5)");
    m.finish();
    body.material = material;
  }
  return body;
}

DirichletSpec read_dirichlet(ObjectReader& r, int components) {
  DirichletSpec d;
  d.group = r.required<int>("group");
  d.dim = r.optional<int>("dim", 1);
  if (d.dim != 0 && d.dim != 1) r.fail(r.path("dim"), "must be 1 (a physical curve) or 0 (a physical point)");
  d.components = r.optional<std::vector<int>>("components", {});
  for (int c : d.components)
    if (c < 0 || c >= components)
      r.fail(r.path("components"), "entry " + std::to_string(c) + " is not a component in [0, " +
                                       std::to_string(components) + ")");
  d.value = r.optional<double>("value", 0.0);
  return d;
}

ContactSpec read_contact(ObjectReader& r) {
  ContactSpec c;
  c.slave = r.required<int>("slave");
  c.obstacle = r.has("obstacle");
  if (c.obstacle) {
    ObjectReader o(r.child("obstacle"), r.file(), r.path("obstacle"));
    c.obstacle_point = pair_of_numbers(o, "point");
    c.obstacle_normal = pair_of_numbers(o, "normal");
    o.finish();
    if (r.has("master")) r.fail(r.path("master"), "give a master curve or an obstacle, not both");
  } else {
    c.master = r.required<int>("master");
  }
  c.search_distance = r.optional<double>("search_distance", c.search_distance);
  if (!(c.search_distance > 0)) r.fail(r.path("search_distance"), "must be > 0");
  c.gap = r.optional<double>("gap", 0.0);
  return c;
}

SolverSpec read_solver(ObjectReader& r) {
  SolverSpec s;
  s.variant = r.optional<std::string>("variant", "");
  s.factor = r.optional<std::string>("factor", s.factor);
  s.preconditioner = r.optional<std::string>("preconditioner", s.preconditioner);
  s.algorithm = r.optional<std::string>("algorithm", s.algorithm);
  s.expansion = r.optional<std::string>("expansion", s.expansion);
  s.stop = r.optional<std::string>("stop", s.stop);
  s.threads = r.optional<long>("threads", s.threads);
  s.maxit = r.optional<long>("maxit", s.maxit);
  s.verbosity = r.optional<long>("verbosity", s.verbosity);
  s.tol = r.optional<double>("tol", s.tol);
  for (auto [key, slot] : {std::pair{"rho", &s.rho}, {"M", &s.M}, {"eta", &s.eta}, {"gamma", &s.gamma}})
    if (r.has(key)) *slot = r.required<double>(key);
  return s;
}

OutputSpec read_output(ObjectReader& r) {
  OutputSpec o;
  o.views = r.optional<std::string>("views", "");
  o.table = r.optional<std::string>("table", "");
  o.stress_table = r.optional<std::string>("stress_table", "");
  o.getdp_solution = r.optional<std::string>("getdp_solution", "");
  o.history = r.optional<std::string>("history", "");
  return o;
}

}  // namespace

ProblemFile read_problem_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the problem file");
  json root;
  try {
    root = json::parse(in);
  } catch (const json::parse_error& error) {
    throw InputError(path + ": not valid JSON (" + error.what() + ")");
  }
  ProblemFile problem;
  problem.path = path;
  const auto slash = path.find_last_of('/');
  problem.directory = slash == std::string::npos ? "." : path.substr(0, slash);

  ObjectReader r(root, path, "");
  problem.mesh = r.required<std::string>("mesh");
  problem.components = r.optional<int>("components", 2);
  if (problem.components != 1 && problem.components != 2)
    r.fail("components", "must be 1 (scalar field) or 2 (plane displacements)");
  problem.bodies = read_list<BodySpec>(r, "bodies", false, read_body);
  if (problem.bodies.empty()) problem.bodies.resize(1);
  const int body_count = static_cast<int>(problem.bodies.size());
  problem.subdomains = read_list<SubdomainSpec>(r, "subdomains", true, [&](ObjectReader& s) {
    return read_subdomain(s, body_count);
  });
  if (problem.subdomains.empty()) r.fail("subdomains", "needs at least one subdomain");
  problem.dirichlet = read_list<DirichletSpec>(r, "dirichlet", false, [&](ObjectReader& d) {
    return read_dirichlet(d, problem.components);
  });
  problem.contact = read_list<ContactSpec>(r, "contact", false, read_contact);
  if (r.has("solver")) {
    ObjectReader s(r.child("solver"), path, "solver");
    problem.solver = read_solver(s);
    s.finish();
  }
  if (r.has("output")) {
    ObjectReader o(r.child("output"), path, "output");
    problem.output = read_output(o);
    o.finish();
  }
  r.finish();
  return problem;
}

}  // namespace ffeti::native

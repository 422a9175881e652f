#include "native/problem_file.h"

#include "base/errors.h"
#include "constraints/capabilities.h"
#include "constraints/contact/contact_discretization.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
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
  /// The value of `key` if its JSON type is T's: no silent conversion (0.7 to an integer,
  /// true to 1, 101.9 to 101).
  template <class T>
  T get(const std::string& key) {
    known_.insert(key);
    const json& value = object_.at(key);
    if (!has_type<T>(value)) fail(path(key), std::string("must be ") + type_name<T>() + ", got " + value.dump());
    return value.get<T>();
  }

  template <class T>
  static bool has_type(const json& value) {
    if constexpr (std::is_same_v<T, std::string>) return value.is_string();
    else if constexpr (std::is_same_v<T, bool>) return value.is_boolean();
    else if constexpr (std::is_integral_v<T>) return value.is_number_integer() && fits<T>(value);
    else if constexpr (std::is_floating_point_v<T>) return value.is_number();
    else return value.is_array() && std::all_of(value.begin(), value.end(), has_type<typename T::value_type>);
  }

  /// An integer of the file within T's range: nlohmann keeps 64 bits, and get<int>() of a
  /// larger value wraps (a group 4294967297 was read as group 1).
  template <class T>
  static bool fits(const json& value) {
    if (value.is_number_unsigned())
      return value.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<T>::max());
    const auto v = value.get<std::int64_t>();  // signed: within int64's range already
    return v >= std::numeric_limits<T>::min() && v <= std::numeric_limits<T>::max();
  }

  template <class T>
  static const char* type_name() {
    if constexpr (std::is_same_v<T, std::string>) return "a string";
    else if constexpr (std::is_same_v<T, bool>) return "true or false";
    else if constexpr (std::is_integral_v<T>) return sizeof(T) < 8 ? "an integer between -2^31 and 2^31 - 1" : "an integer";
    else if constexpr (std::is_floating_point_v<T>) return "a number";
    else if constexpr (std::is_integral_v<typename T::value_type>)
      return sizeof(typename T::value_type) < 8 ? "a list of integers between -2^31 and 2^31 - 1" : "a list of integers";
    else return "a list of numbers";
  }

  const json& object_;
  std::string file_, where_;
  std::set<std::string> known_;
};

/// The entries of the list `key` (an error if absent and `required`), each read by
/// `read_one(reader)`.
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

SubdomainSpec read_subdomain(ObjectReader& r, int body_count, int components) {
  SubdomainSpec sub;
  // Plane problems are cut into physical surfaces, solids into physical volumes: a key of
  // the other kind means the mesh or "components" is not what the file's author thinks.
  const bool solid = components == 3;
  const std::string key = solid ? "volumes" : "surfaces", other = solid ? "surfaces" : "volumes";
  if (r.has(other))
    r.fail(r.path(other), solid ? "a solid (\"components\": 3) is cut into physical volumes: give \"volumes\""
                                : "physical volumes need \"components\": 3 (a solid); a plane problem gives \"surfaces\"");
  sub.regions = r.required<std::vector<int>>(key);
  if (sub.regions.empty()) r.fail(r.path(key), solid ? "needs at least one physical volume" : "needs at least one physical surface");
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

BodySpec read_body(ObjectReader& r, int components) {
  BodySpec body;
  body.name = r.optional<std::string>("name", "");
  if (r.has("material")) {
    ObjectReader m(r.child("material"), r.file(), r.path("material"));
    MaterialSpec material;
    material.young = m.required<double>("E");
    material.poisson = m.required<double>("nu");
    if (components == 3 && m.has("model"))
      m.fail(m.path("model"), "applies to plane problems only (a solid, \"components\": 3, has neither plane strain "
                              "nor plane stress)");
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
  // Default: a group of the boundary's dimension (curves in 2D, surfaces in 3D).
  const int boundary = components == 3 ? 2 : 1;
  d.dim = r.optional<int>("dim", boundary);
  if (boundary == 1 && d.dim != 0 && d.dim != 1)
    r.fail(r.path("dim"), "must be 1 (a physical curve) or 0 (a physical point)");
  if (boundary == 2 && (d.dim < 0 || d.dim > 2))
    r.fail(r.path("dim"), "must be 2 (a physical surface), 1 (a curve) or 0 (a point)");
  d.components = r.optional<std::vector<int>>("components", {});
  if (r.has("components") && d.components.empty())
    r.fail(r.path("components"), "is empty: it would fix no component; leave the key out to fix every component");
  for (int c : d.components)
    if (c < 0 || c >= components)
      r.fail(r.path("components"), "entry " + std::to_string(c) + " is not a component in [0, " +
                                       std::to_string(components) + ")");
  d.value = r.optional<double>("value", 0.0);
  return d;
}

/// The key of a kind that owns its input (KindInput::file_key), one entry per field, into
/// c.kind_parameters; the unit's checks name the key instead of the script's argument. Its
/// line key (KindInput::line_key) instead: the curve into c.line_curve, the entries read
/// from the mesh (native/contact_input.cpp).
void read_kind_input(ObjectReader& r, const ContactDiscretization& unit, int dimension, ContactSpec& c) {
  const KindInput& spec = *unit.input();
  ObjectReader o(r.child(spec.file_key), r.file(), r.path(spec.file_key));
  if (spec.line_key && o.has(spec.line_key)) {
    const std::string point = spec.fields[0].key, normal = spec.fields[1].key;
    c.line_curve = o.required<int>(spec.line_key);
    if (o.has(point) || o.has(normal))
      o.fail(o.path(spec.line_key), "give a curve or a " + point + " and a " + normal + ", not both");
    if (dimension == 3)
      o.fail(o.path(spec.line_key), std::string("a plane problem's ") + unit.capabilities().name + " line; a solid's " +
                                        "plane takes \"" + point + "\" and \"" + normal + "\"");
    o.finish();
    c.kind_parameters[unit.kind()] = {};
    return;
  }
  std::vector<std::vector<double>> given;  // per field, empty where left out
  for (const InputField& field : spec.fields)
    given.push_back(!o.has(field.key) ? std::vector<double>{}
                    : field.flag      ? std::vector<double>{o.required<bool>(field.key) ? 1.0 : 0.0}
                    : field.size == 1 ? std::vector<double>{o.required<double>(field.key)}
                                      : o.required<std::vector<double>>(field.key));
  o.finish();
  try {
    std::vector<double> values = input_values(spec, given, dimension, r.file() + ": " + o.path(""));
    unit.check_input(values, dimension);
    require(unit.kind(), Feature::ffeti_solve, dimension, spec.argument);
    c.kind_parameters[unit.kind()] = std::move(values);
  } catch (const InputError& error) {
    const std::string what = error.what(), argument = std::string(spec.argument) + ": ";
    if (what.rfind(argument, 0) == 0) o.fail(r.path(spec.file_key), what.substr(argument.size()));
    throw;
  }
}

ContactSpec read_contact(ObjectReader& r, int components) {
  ContactSpec c;
  const int dimension = components == 3 ? 3 : 2;
  c.slave = r.required<int>("slave");
  // The kind this entry makes (its row says where friction works): a kind's own key, else
  // the list kind of the problem's components (its key names the master group).
  const ContactDiscretization* list_kind = file_list_kind(components);
  const std::string master_key = list_kind->list_input()->file_key;
  c.kind = list_kind->kind();
  for (const ContactDiscretization* unit : kinds_with_input()) {
    const char* key = unit->input()->file_key;
    if (!key || !r.has(key)) continue;
    if (c.rigid()) r.fail(r.path(key), "give one obstacle per contact entry");
    read_kind_input(r, *unit, dimension, c);
    c.kind = unit->kind();
  }
  const ContactKind kind = c.kind;
  if (c.rigid()) {
    if (components < 2) r.fail(r.path("obstacle"), "needs displacements (\"components\": 2 or 3)");
    if (r.has(master_key)) r.fail(r.path(master_key), "give a master curve or an obstacle, not both");
  } else {
    c.master = r.required<int>(master_key);
  }
  // Each option only where it means something: node to segment or face searches, node to node has a gap,
  // node to face a contact_normal.
  const bool projected = !c.rigid() && list_kind->searched_argument();
  if (r.has("search_distance")) {
    if (!projected)
      r.fail(r.path("search_distance"), "applies to node-to-segment or node-to-face contact (2 or 3 components, a master "
                                        "group) only");
    c.search_distance = r.required<double>("search_distance");
    if (!(*c.search_distance > 0)) r.fail(r.path("search_distance"), "must be > 0");
  }
  for (const KindOption& given : list_options()) {  // the list kinds' own keys, read through the registry
    const ListOption& option = *given.option;
    if (!r.has(option.file_key)) continue;
    if (c.rigid() || given.kind != list_kind) r.fail(r.path(option.file_key), std::string("applies to ") + option.applies + " only");
    if (option.words.empty()) {
      c.options[given.index] = r.required<double>(option.file_key);
      continue;
    }
    const std::string word = r.required<std::string>(option.file_key);
    const int at = word_position(option, word);
    if (at < 0) r.fail(r.path(option.file_key), word_refusal(option, word));
    c.options[given.index] = at;
  }
  for (const auto& [key, law] : {std::pair<const char*, std::optional<double>*>{"friction", &c.friction},
                                 std::pair<const char*, std::optional<double>*>{"slip_bound", &c.slip_bound}}) {
    if (!r.has(key)) continue;
    if (!supports(kind, Feature::friction, dimension)) r.fail(r.path(key), unsupported(kind, Feature::friction, dimension));
    *law = r.required<double>(key);
    if (!(**law >= 0)) r.fail(r.path(key), "must be >= 0");
  }
  if (c.friction && c.slip_bound) r.fail(r.path("slip_bound"), "give one law, friction (Coulomb) or slip_bound (Tresca)");
  if (c.slave == c.master) r.fail(r.path(master_key), dimension == 3 ? "is the slave surface" : "is the slave curve");
  return c;
}

/// Every key of "solver" is an option of the registry (service/options.h), read as its kind
/// asks and checked there.
GivenOptions read_solver(ObjectReader& r, const json& object) {
  GivenOptions given;
  for (const auto& [key, value] : object.items()) {
    const Option* option = find_option(key);
    if (!option || !r.has(key)) continue;  // finish() refuses it as an unknown key
    try {
      if (option->kind == OptionKind::word) given.set(key, r.required<std::string>(key));
      else if (option->kind == OptionKind::integer) given.set(key, r.required<long>(key));
      else given.set(key, r.required<double>(key));
    } catch (const InputError& error) {
      const std::string what = error.what();
      // The registry's messages begin with the option's name; the reader's name file and key.
      if (what.rfind(key + ": ", 0) == 0) r.fail(r.path(key), what.substr(key.size() + 2));
      throw;
    }
  }
  return given;
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

/// output.getdp_solution numbers its solutions by the systems of one .pre file: checked
/// before any work, not after the solve.
void check_getdp_solution(const ProblemFile& problem) {
  if (problem.output.getdp_solution.empty()) return;
  const std::string where = problem.path + ": output.getdp_solution: ";
  const std::string pre = resolve(problem, problem.subdomains.front().dofs.getdp_pre);
  std::set<int> systems;
  for (size_t s = 0; s < problem.subdomains.size(); ++s) {
    const DofMapSpec& dofs = problem.subdomains[s].dofs;
    if (dofs.getdp_pre.empty() || resolve(problem, dofs.getdp_pre) != pre)
      throw InputError(where + "needs every subdomain's dofs from one GetDP .pre file; subdomains[" + std::to_string(s) +
                       "] differs from subdomains[0]");
    if (!systems.insert(dofs.system).second)
      throw InputError(where + "system " + std::to_string(dofs.system) + " is the dof map of two subdomains");
  }
}

/// Each output file must have the extension of the format written to it (gmsh chooses its
/// format by the extension, so a view named .txt was written as something else), and may
/// not be one of the input files or another output (the first write would destroy it).
void check_output_paths(const ProblemFile& problem) {
  const OutputSpec& out = problem.output;
  const std::vector<std::pair<const char*, const std::string*>> outputs = {
      {"views", &out.views}, {"table", &out.table}, {"stress_table", &out.stress_table},
      {"getdp_solution", &out.getdp_solution}, {"history", &out.history}};
  const std::map<std::string, std::vector<std::string>> extensions = {
      {"views", {".msh", ".pos"}}, {"table", {".csv"}}, {"stress_table", {".csv"}},
      {"getdp_solution", {".res"}}, {"history", {".csv"}}};
  std::map<std::string, std::string> taken;  // canonical path -> what it is
  const auto canonical = [&](const std::string& path) {
    return std::filesystem::weakly_canonical(resolve(problem, path)).string();
  };
  taken[std::filesystem::weakly_canonical(problem.path).string()] = "the problem file";
  taken[canonical(problem.mesh)] = "the mesh file";
  for (size_t s = 0; s < problem.subdomains.size(); ++s) {
    const SubdomainSpec& sub = problem.subdomains[s];
    const std::string where = "subdomains[" + std::to_string(s) + "]";
    for (const auto& [path, what] : {std::pair{&sub.matrix, ".matrix"}, {&sub.rhs, ".rhs"},
                                     {&sub.dofs.getdp_pre, ".dofs.getdp"}, {&sub.dofs.explicit_file, ".dofs.file"}})
      if (!path->empty()) taken.emplace(canonical(*path), where + what);
  }
  for (const auto& [key, path] : outputs) {
    if (path->empty()) continue;
    const std::string where = problem.path + ": output." + key + ": ";
    const std::string extension = std::filesystem::path(*path).extension().string();
    const auto& allowed = extensions.at(key);
    if (std::find(allowed.begin(), allowed.end(), extension) == allowed.end()) {
      std::string list;
      for (const std::string& e : allowed) list += (list.empty() ? "" : " or ") + e;
      throw InputError(where + "\"" + *path + "\" needs the extension " + list + " (the format written)");
    }
    const auto [it, fresh] = taken.emplace(canonical(*path), std::string("output.") + key);
    if (!fresh) throw InputError(where + "\"" + *path + "\" is " + it->second + ": writing it would destroy that file");
  }
}

}  // namespace

std::string resolve(const ProblemFile& problem, const std::string& path) {
  return path.empty() || path[0] == '/' ? path : problem.directory + "/" + path;
}

ProblemFile read_problem_file(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw InputError(path + ": is a folder, not a problem file");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the problem file");
  json root;
  // JSON lets a key appear twice in one object and keeps the last: a problem file that says
  // one thing twice most likely means neither, so it is refused.
  std::vector<std::set<std::string>> keys;  // of each object being parsed
  std::string duplicate, last_key;  // last_key: where a number that overflows stands
  const json::parser_callback_t find_duplicates = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    else if (event == json::parse_event_t::object_end) keys.pop_back();
    else if (event == json::parse_event_t::key) {
      last_key = parsed.get<std::string>();
      if (!keys.back().insert(last_key).second && duplicate.empty()) duplicate = last_key;
    }
    return true;
  };
  try {
    root = json::parse(in, find_duplicates);
  } catch (const json::parse_error& error) {
    throw InputError(path + ": not valid JSON (" + error.what() + ")");
  } catch (const json::out_of_range& error) {  // a number beyond double, e.g. 1e999
    throw InputError(path + ": the value of key \"" + last_key + "\" is a number beyond what a double holds (" +
                     error.what() + ")");
  }
  if (!duplicate.empty())
    throw InputError(path + ": key \"" + duplicate + "\" appears twice in one object (the last would silently win)");
  ProblemFile problem;
  problem.path = path;
  const auto slash = path.find_last_of('/');
  problem.directory = slash == std::string::npos ? "." : path.substr(0, slash);

  ObjectReader r(root, path, "");
  problem.mesh = r.required<std::string>("mesh");
  problem.components = r.optional<int>("components", 2);
  if (problem.components < 1 || problem.components > 3)
    r.fail("components", "must be 1 (scalar field), 2 (plane displacements) or 3 (displacements of a solid)");
  const bool bodies_given = r.has("bodies");
  problem.bodies = read_list<BodySpec>(r, "bodies", false, [&](ObjectReader& b) {
    return read_body(b, problem.components);
  });
  if (bodies_given && problem.bodies.empty()) r.fail("bodies", "needs at least one body (or leave it out: one body)");
  if (problem.bodies.empty()) problem.bodies.resize(1);
  const int body_count = static_cast<int>(problem.bodies.size());
  problem.subdomains = read_list<SubdomainSpec>(r, "subdomains", true, [&](ObjectReader& s) {
    return read_subdomain(s, body_count, problem.components);
  });
  if (problem.subdomains.empty()) r.fail("subdomains", "needs at least one subdomain");
  problem.dirichlet = read_list<DirichletSpec>(r, "dirichlet", false, [&](ObjectReader& d) {
    return read_dirichlet(d, problem.components);
  });
  problem.contact = read_list<ContactSpec>(r, "contact", false, [&](ObjectReader& c) {
    return read_contact(c, problem.components);
  });
  for (size_t i = 0; i < problem.contact.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (problem.contact[i].slave == problem.contact[j].slave)
        r.fail("contact[" + std::to_string(i) + "].slave", std::string(problem.components == 3 ? "surface " : "curve ") +
                                                             std::to_string(problem.contact[i].slave) +
                                                             " is already the slave of contact[" + std::to_string(j) + "]");
  if (r.has("solver")) {
    ObjectReader s(r.child("solver"), path, "solver");
    problem.solver = read_solver(s, r.child("solver"));
    s.finish();
  }
  if (r.has("output")) {
    ObjectReader o(r.child("output"), path, "output");
    problem.output = read_output(o);
    o.finish();
  }
  r.finish();
  check_getdp_solution(problem);
  check_output_paths(problem);
  return problem;
}

}  // namespace ffeti::native

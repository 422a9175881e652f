#include "native/system_files.h"

#include "base/errors.h"

#include <cholmod.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

namespace ffeti::native {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::ifstream open_text(const std::string& path, const char* what) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the " + std::string(what) + " file");
  return in;
}

/// True if the Matrix Market banner declares real (or integer) values.
bool real_banner(const std::string& path) {
  std::ifstream in(path);
  std::string banner, object, format, field;
  in >> banner >> object >> format >> field;
  std::transform(field.begin(), field.end(), field.begin(), [](unsigned char c) { return std::tolower(c); });
  return field == "real" || field == "integer";
}

/// Where a Matrix Market file CHOLMOD could not read goes wrong: the first line that is not
/// what the format asks for (the banner, the size line, an entry with its indices in
/// range and a number), as "line N: what"; empty if every line looks right.
std::string first_bad_line(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  long number = 0, rows = -1, columns = -1, entries = -1, seen = 0;
  bool coordinate = false;
  const auto where = [&](const std::string& what) { return "line " + std::to_string(number) + ": " + what; };
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) {
      if (line.rfind("%%MatrixMarket", 0) != 0) return where("the banner %%MatrixMarket ... is missing");
      coordinate = line.find("coordinate") != std::string::npos;
      continue;
    }
    if (line.empty() || line[0] == '%') continue;
    std::istringstream fields(line);
    if (rows < 0) {
      if (!(fields >> rows >> columns) || (coordinate && !(fields >> entries)) || rows < 0 || columns < 0)
        return where("the size line needs " + std::string(coordinate ? "rows, columns and entries" : "rows and columns") +
                     ", got \"" + line + "\"");
      continue;
    }
    long i = 0, j = 0;
    double value = 0;
    if (coordinate && !(fields >> i >> j >> value))
      return where("an entry needs a row, a column and a value, got \"" + line + "\"");
    if (!coordinate && !(fields >> value)) return where("a value is not a number: \"" + line + "\"");
    if (coordinate && (i < 1 || i > rows || j < 1 || j > columns))
      return where("the entry (" + std::to_string(i) + ", " + std::to_string(j) + ") lies outside the " +
                   std::to_string(rows) + " x " + std::to_string(columns) + " matrix");
    ++seen;
  }
  if (rows < 0) return where("the size line is missing");
  const long expected = coordinate ? entries : rows * columns;
  if (seen != expected)
    return "the size line announces " + std::to_string(expected) + " entries, the file has " + std::to_string(seen);
  return "";
}

/// A Matrix Market file read by CHOLMOD: sparse with both triangles, or dense.
class MarketFile {
 public:
  explicit MarketFile(const std::string& path) : path_(path) {
    cholmod_start(&common_);
    common_.print = 0;  // errors come back to us as a null result, worded below
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "r"), std::fclose);
    if (!file) {
      cholmod_finish(&common_);
      throw InputError(path + ": cannot open the Matrix Market file");
    }
    data_ = cholmod_read_matrix(file.get(), 1, &type_, &common_);
    if (!data_) {
      cholmod_finish(&common_);
      const std::string bad = first_bad_line(path);
      throw InputError(path + ": not a valid Matrix Market file (CHOLMOD could not read it" +
                       (bad.empty() ? std::string(")") : "; " + bad + ")"));
    }
    const int xtype = type_ == CHOLMOD_SPARSE ? static_cast<cholmod_sparse*>(data_)->xtype
                                              : static_cast<cholmod_dense*>(data_)->xtype;
    if (xtype != CHOLMOD_REAL || !real_banner(path)) {  // CHOLMOD reads a pattern as ones
      release();
      throw InputError(path + ": needs real values (the file is a pattern or complex Matrix Market file)");
    }
  }
  ~MarketFile() { release(); }

  MarketFile(const MarketFile&) = delete;
  MarketFile& operator=(const MarketFile&) = delete;

  SparseMatrix sparse() const {
    if (type_ != CHOLMOD_SPARSE) throw InputError(path_ + ": a matrix needs the Matrix Market coordinate format");
    const auto* a = static_cast<const cholmod_sparse*>(data_);
    if (a->nrow != a->ncol)
      throw InputError(path_ + ": the matrix is " + std::to_string(a->nrow) + " x " + std::to_string(a->ncol) +
                       ", not square");
    std::vector<Eigen::Triplet<double>> entries;
    const auto* p = static_cast<const int*>(a->p);
    const auto* i = static_cast<const int*>(a->i);
    const auto* x = static_cast<const double*>(a->x);
    for (size_t col = 0; col < a->ncol; ++col)
      for (int k = p[col]; k < p[col + 1]; ++k)
        entries.emplace_back(i[k], static_cast<int>(col), x[k]);
    SparseMatrix matrix(static_cast<Eigen::Index>(a->nrow), static_cast<Eigen::Index>(a->ncol));
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
  }

  Vec dense_column() const {
    if (type_ != CHOLMOD_DENSE) throw InputError(path_ + ": a vector needs the Matrix Market array format");
    const auto* a = static_cast<const cholmod_dense*>(data_);
    if (a->ncol != 1)
      throw InputError(path_ + ": a vector needs one column, the file has " + std::to_string(a->ncol));
    return Eigen::Map<const Vec>(static_cast<const double*>(a->x), static_cast<Eigen::Index>(a->nrow));
  }

 private:
  void release() {  // the data and the CHOLMOD workspace, once
    if (type_ == CHOLMOD_SPARSE) {
      auto* sparse = static_cast<cholmod_sparse*>(data_);
      cholmod_free_sparse(&sparse, &common_);
    } else if (type_ == CHOLMOD_DENSE) {
      auto* dense = static_cast<cholmod_dense*>(data_);
      cholmod_free_dense(&dense, &common_);
    }
    cholmod_finish(&common_);
  }

  std::string path_;
  cholmod_common common_;
  void* data_ = nullptr;
  int type_ = -1;
};

/// The lines between GetDP's "... = [" and "];", the rest of the file skipped.
std::vector<std::string> getdp_block(std::istream& in, const std::string& path, std::string* header) {
  std::string line;
  while (std::getline(in, line) && line.find("= [") == std::string::npos) *header += line + "\n";
  if (!in) throw InputError(path + ": no \"= [\" block: not a matrix or vector written by GetDP's Print[]");
  std::vector<std::string> lines;
  while (std::getline(in, line)) {
    if (line.rfind("];", 0) == 0) return lines;
    lines.push_back(line);
  }
  throw InputError(path + ": the block is not closed by \"];\" (file cut short?)");
}

[[noreturn]] void bad_line(const std::string& path, size_t line, const std::string& what) {
  throw InputError(path + ": entry " + std::to_string(line + 1) + ": " + what);
}

SparseMatrix read_getdp_matrix(const std::string& path) {
  std::ifstream in = open_text(path, "matrix");
  std::string header;
  const std::vector<std::string> lines = getdp_block(in, path, &header);
  long rows = -1, cols = -1;
  const auto size = header.find("Size =");
  if (size == std::string::npos || !(std::istringstream(header.substr(size + 6)) >> rows >> cols))
    throw InputError(path + ": no \"% Size = rows cols\" line: not a matrix written by GetDP's Print[]");
  if (rows != cols) throw InputError(path + ": the matrix is " + std::to_string(rows) + " x " +
                                     std::to_string(cols) + ", not square");
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(lines.size());
  for (size_t k = 0; k < lines.size(); ++k) {
    long i = 0, j = 0;
    double value = 0;
    if (!(std::istringstream(lines[k]) >> i >> j >> value)) bad_line(path, k, "not \"row column value\"");
    if (i < 1 || i > rows || j < 1 || j > cols)
      bad_line(path, k, "(" + std::to_string(i) + ", " + std::to_string(j) + ") lies outside the declared " +
                            std::to_string(rows) + " x " + std::to_string(cols));
    entries.emplace_back(static_cast<int>(i - 1), static_cast<int>(j - 1), value);
  }
  SparseMatrix matrix(rows, cols);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

Vec read_getdp_vector(const std::string& path) {
  std::ifstream in = open_text(path, "vector");
  std::string header;
  const std::vector<std::string> lines = getdp_block(in, path, &header);
  Vec values(static_cast<Eigen::Index>(lines.size()));
  for (size_t k = 0; k < lines.size(); ++k)
    if (!(std::istringstream(lines[k]) >> values[static_cast<Eigen::Index>(k)])) bad_line(path, k, "not a number");
  return values;
}

/// Checks that every row 0..n-1 got one location.
std::vector<DofLocation> complete(std::map<long, DofLocation> rows, const std::string& path) {
  std::vector<DofLocation> map;
  long expected = 0;
  for (const auto& [row, location] : rows) {
    if (row != expected) throw InputError(path + ": row " + std::to_string(expected + 1) + " has no dof");
    map.push_back(location);
    ++expected;
  }
  return map;
}

}  // namespace

SparseMatrix read_matrix(const std::string& path) {
  return ends_with(path, ".mtx") ? MarketFile(path).sparse() : read_getdp_matrix(path);
}

Vec read_vector(const std::string& path) {
  return ends_with(path, ".mtx") ? MarketFile(path).dense_column() : read_getdp_vector(path);
}

std::vector<DofLocation> read_getdp_dof_map(const std::string& path, int system, int components) {
  std::ifstream in = open_text(path, "GetDP .pre");
  std::string line;
  int block = -1;
  while (block < system && std::getline(in, line))
    if (line.rfind("$DofData", 0) == 0) ++block;
  if (block < system)
    throw InputError(path + ": no system " + std::to_string(system) + " (the file has " + std::to_string(block + 1) +
                     " $DofData blocks, counted from 0)");
  // Four lines of numbers (resolution and system, function spaces, time functions,
  // partitions), then the dof counts.
  for (int k = 0; k < 4; ++k) std::getline(in, line);
  long any = 0, unknowns = 0;
  if (!(in >> any >> unknowns)) throw InputError(path + ": system " + std::to_string(system) + ": no dof counts");
  std::map<long, std::pair<long, long>> rows;  // equation -> (basis function, node)
  for (long k = 0; k < any; ++k) {
    long basis = 0, entity = 0, harmonic = 0, type = 0;
    if (!(in >> basis >> entity >> harmonic >> type))
      throw InputError(path + ": system " + std::to_string(system) + ": dof " + std::to_string(k + 1) + " unreadable");
    std::getline(in, line);
    std::istringstream data(line);
    // GetDP's dof types: 1 unknown, 5 unknown with an initial value; the others (2, 3, 4, 6
    // fixed, 7, 8 linked) come from a Constraint.
    if (type != 1 && type != 5)
      throw InputError(path + ": system " + std::to_string(system) + " has dofs of GetDP type " + std::to_string(type) +
                       " (fixed or linked by a Constraint): assemble the subdomain systems without constraints "
                       "and name the fixed groups in the problem file's \"dirichlet\"");
    long equation = 0;
    if (!(data >> equation) || equation < 1 || equation > unknowns)
      throw InputError(path + ": system " + std::to_string(system) + ": dof " + std::to_string(k + 1) +
                       " has no equation number in [1, " + std::to_string(unknowns) + "]");
    if (!rows.emplace(equation - 1, std::make_pair(basis, entity)).second)
      throw InputError(path + ": system " + std::to_string(system) + ": equation " + std::to_string(equation) +
                       " is numbered twice");
  }
  std::map<long, int> component_of_basis;
  for (const auto& [row, dof] : rows) component_of_basis.emplace(dof.first, 0);
  if (static_cast<int>(component_of_basis.size()) != components)
    throw InputError(path + ": system " + std::to_string(system) + " has " +
                     std::to_string(component_of_basis.size()) + " basis functions, the problem has " +
                     std::to_string(components) + " components (one nodal basis function per component)");
  int next = 0;
  for (auto& [basis, component] : component_of_basis) component = next++;
  std::map<long, DofLocation> located;
  for (const auto& [row, dof] : rows)
    located[row] = {static_cast<NodeTag>(dof.second), component_of_basis[dof.first]};
  return complete(std::move(located), path);
}

std::vector<DofLocation> read_explicit_dof_map(const std::string& path, int components) {
  std::ifstream in = open_text(path, "dof map");
  std::map<long, DofLocation> rows;
  std::string line;
  long row = 0;
  for (long number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    long node = 0, component = -1;
    if (!(std::istringstream(line) >> node >> component) || node < 1 || component < 0 || component >= components)
      throw InputError(path + ": line " + std::to_string(number) + ": needs \"node_tag component\" with a node tag "
                       ">= 1 and a component in [0, " + std::to_string(components) + ")");
    rows[row++] = {static_cast<NodeTag>(node), static_cast<int>(component)};
  }
  return complete(std::move(rows), path);
}

}  // namespace ffeti::native

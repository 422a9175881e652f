#include "service/contact_pressure.h"

#include "base/errors.h"

#include <cmath>
#include <map>
#include <tuple>

namespace ffeti {
namespace {

using NodeKey = std::tuple<int, long long, long long, long long>;  // body and snapped position

NodeKey node_key(int body, double x, double y, double z, double snap) {
  return {body, std::llround(x / snap), std::llround(y / snap), std::llround(z / snap)};
}

}  // namespace

ContactPressure contact_pressure(const FetiProblem& problem, const Vec& lambda, const std::vector<Vec>& share) {
  const Constraints& c = problem.constraints();
  const auto& inputs = problem.inputs();
  const int rows = c.contact_rows();
  collectively(problem.communicator(), [&] {
    if (share.size() != inputs.size()) throw InputError("Share: needs one entry per subdomain");
    for (size_t k = 0; k < inputs.size(); ++k)
      if (share[k].size() != 0 && (share[k].size() != inputs[k].K.rows() || !share[k].allFinite()))
        throw InputError("Share[" + std::to_string(problem.global_ids()[k]) + "]: needs " +
                         std::to_string(inputs[k].K.rows()) + " finite entries, one per dof (or none)");
  });
  std::map<NodeKey, int> row_at;
  for (int i = 0; i < rows; ++i) {
    const auto& [x, y] = problem.contact_positions()[static_cast<size_t>(i)];
    row_at.emplace(node_key(problem.contact_body_component()[static_cast<size_t>(i)][0], x, y,
                            problem.contact_heights()[static_cast<size_t>(i)], problem.snap()),
                   i);
  }
  // The contact row at each local dof's node (-1: none), then (row, share) of the copies
  // held here, summed in rank order: the same on every rank.
  std::vector<std::vector<int>> row_of_dof;
  std::vector<double> local;
  for (size_t k = 0; k < inputs.size(); ++k) {
    const SubdomainInput& in = inputs[k];
    std::vector<int>& rows_here = row_of_dof.emplace_back(static_cast<size_t>(in.K.rows()), -1);
    for (size_t d = 0; d < rows_here.size(); ++d) {
      const auto it = row_at.find(node_key(in.body, in.x[d], in.y[d], in.z.empty() ? 0.0 : in.z[d], problem.snap()));
      if (it == row_at.end()) continue;
      rows_here[d] = it->second;
      const int component = in.component.empty() ? 0 : in.component[d];
      if (share[k].size() && component == problem.contact_body_component()[static_cast<size_t>(it->second)][1])
        local.insert(local.end(), {double(it->second), share[k][static_cast<Eigen::Index>(d)]});
    }
  }
  const std::vector<double> all = problem.communicator().allgather(local);
  ContactPressure result;
  result.share_per_row = Vec::Zero(rows);
  for (size_t p = 0; p + 2 <= all.size(); p += 2) result.share_per_row[static_cast<Eigen::Index>(all[p])] += all[p + 1];
  result.per_row = Vec::Zero(rows);
  std::string missing;
  for (int i = 0; i < rows; ++i) {
    const double force = lambda.size() ? lambda[c.equality_rows + i] : 0.0;
    if (result.share_per_row[i] > 0) result.per_row[i] = force / result.share_per_row[i];
    else if (force != 0 && missing.empty()) {
      const auto& [x, y] = problem.contact_positions()[static_cast<size_t>(i)];
      missing = "Share: the contact node at (" + std::to_string(x) + ", " + std::to_string(y) +
                ") carries a force but has no positive share of the contact curve or surface (integrate the "
                "test functions over the contact boundary of every subdomain holding it)";
    }
  }
  if (!missing.empty()) throw InputError(missing);  // the same on every rank: built from gathered data
  for (const std::vector<int>& rows_here : row_of_dof) {
    Vec pressure = Vec::Zero(static_cast<Eigen::Index>(rows_here.size()));
    for (size_t d = 0; d < rows_here.size(); ++d)
      if (rows_here[d] >= 0) pressure[static_cast<Eigen::Index>(d)] = result.per_row[rows_here[d]];
    result.per_dof.push_back(std::move(pressure));
  }
  return result;
}

}  // namespace ffeti

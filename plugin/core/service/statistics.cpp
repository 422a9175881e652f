#include "service/statistics.h"

#include "service/options.h"
#include "parallel/process.h"
#include "feti/held_bytes.h"

#include <sstream>

namespace ffeti {

int status_code(SolveStatus status) { return static_cast<int>(status); }

Statistics statistics(const FetiProblem& problem, const FetiResult* result) {
  const Constraints& c = problem.constraints();
  const PhaseTimes& setup = problem.setup_times();
  Statistics s = {
      {"ranks", problem.communicator().size()},
      {"subdomains", problem.subdomain_count()},
      {"local_subdomains", problem.local_subdomain_count()},
      {"primal", static_cast<double>(problem.primal_dimension())},
      {"dual", problem.dual_dimension()},
      {"equality_rows", c.equality_rows},
      {"gluing_rows", c.count(RowKind::gluing)},
      {"dirichlet_rows", c.count(RowKind::dirichlet)},
      {"couples", c.count(RowKind::contact)},
      {"floating", problem.floating_subdomains()},
      {"coarse", problem.coarse_dimension()},
      {"factor_nnz", problem.factor_nonzeros()},
      {"factor_bytes", problem.factor_bytes()},
      {"operator_bytes", problem.operator_bytes()},
      {"factor_flops", problem.factor_flops()},
      {"input_bytes", problem.input_bytes()},
      {"kernel_bytes", problem.kernel_bytes()},
      {"constraint_bytes", constraint_bytes(c)},  // this rank's rows
      {"dual_rows_bytes", problem.dual_bytes().rows},
      {"coarse_bytes", problem.dual_bytes().coarse},
      {"preconditioner_bytes", problem.dual_bytes().preconditioner},
      {"factorizations", static_cast<double>(problem.factorizations())},
      {"shared_factors", static_cast<double>(problem.shared_factors())},
      {"supernodal_factors", static_cast<double>(problem.supernodal_factors())},
      {"interface_factors", static_cast<double>(problem.interface_factors())},
      {"symbolic_analyses", static_cast<double>(problem.symbolic_analyses())},
      {"explicit_operators", static_cast<double>(problem.explicit_operators())},
      {"explicit_bytes", problem.explicit_bytes()},
      {"time_explicit", problem.explicit_seconds()},
      {"time_constraints", setup.constraints},
      {"time_factor", setup.factorization},
      {"time_coarse", setup.coarse_space},
      {"time_dual_data", setup.dual_data},
      {"peak_memory_mb", peak_memory_mb()},  // read when asked: the process's peak so far
  };
  s.push_back({"friction_rows", c.friction_rows});  // 0 without friction: a script may ask either way
  s.push_back({"beyond_reach", c.beyond_reach.rows()});
  if (!result) return s;
  const Statistics solve = {
      {"status", status_code(result->status)},
      {"active", result->active_contact},
      {"outer", result->counts.outer},
      {"hessian", result->counts.hessian},
      {"hessian_norm_estimate", result->counts.hessian_norm_estimate},
      {"cg", result->counts.cg},
      {"expansion", result->counts.expansion},
      {"proportioning", result->counts.proportioning},
      {"expansion_fallback", result->counts.expansion_fallback},
      {"settle_steps", result->counts.settle},
      {"penalty_increases", result->counts.penalty_increases},
      {"preconditioner_applications", result->counts.preconditioner},
      {"energy", result->energy},
      {"gradient_norm", result->gradient_norm},
      {"gradient_reference", result->gradient_reference},
      {"violation", result->violation},
      {"scale_evaluations", result->scale_evaluations},
      {"equality_norm", result->equality_norm},
      {"equality_reference", result->equality_reference},
      {"kkt_equilibrium", result->kkt.equilibrium},
      {"kkt_equality", result->kkt.equality},
      {"kkt_inequality", result->kkt.inequality},
      {"kkt_dual", result->kkt.dual_feasibility},
      {"kkt_complementarity", result->kkt.complementarity},
      {"time_norm_estimate", result->times.norm_estimate},
      {"time_free_rows", result->times.free_rows},
      {"time_solve", result->times.solve},
      {"time_dual_operator", result->times.dual_operator},
      {"dual_operator_applications", static_cast<double>(result->dual_operator_applications)},
      {"time_factor_solves", result->times.factor_solves},
      {"time_hessian", result->times.hessian},
      {"time_preconditioner", result->times.preconditioner},
      {"time_primal_checks", result->times.primal_checks},
      {"time_recovery", result->times.recovery},
      {"time_kkt", result->times.kkt},
      {"beyond_reach_penetrating", result->beyond_reach.penetrating},
      {"beyond_reach_depth", result->beyond_reach.depth},
  };
  s.insert(s.end(), solve.begin(), solve.end());
  if (c.friction_rows > 0) {
    const Statistics friction = {
        {"friction_iterations", result->friction_iterations},
        {"friction_bound_change", result->friction_bound_change},
        {"newton_steps", result->newton_steps},
        {"newton_hessian", result->newton_hessian},
        {"slipping", result->slipping_contact},
        {"sliding_body", result->sliding_body},
    };
    s.insert(s.end(), friction.begin(), friction.end());
  }
  return s;
}

std::vector<ContactMultiplier> contact_multipliers(const FetiProblem& problem, const FetiResult* result) {
  const Constraints& c = problem.constraints();
  const bool solved = result && result->lambda.size();
  const ContactRowForces forces = contact_row_forces(c, solved ? result->lambda : Vec(), solved ? result->slip_bound : Vec(),
                                                     solved ? result->slip : Vec());
  std::vector<ContactMultiplier> rows;
  for (int i = c.equality_rows; i < c.first_friction_row(); ++i) {
    const auto k = static_cast<size_t>(i - c.equality_rows);
    const auto& position = problem.contact_positions()[k];
    const ContactRowGeometry& geometry = *c.geometry[k];
    rows.push_back({position[0], position[1], solved ? result->lambda[i] : 0.0, problem.contact_heights()[k],
                    forces.tangential[k], forces.second_tangential[k], forces.state[k], geometry.normal(),
                    geometry.tangents(), forces.slip[k], forces.second_slip[k]});
  }
  return rows;
}

std::string friction_counts(const FetiResult& result) {
  std::string list;
  for (int count : result.friction_hessian) list += (list.empty() ? "" : ",") + std::to_string(count);
  return list;
}

std::string format_rank_report(const FetiProblem& problem) {
  std::ostringstream out;
  out.precision(4);
  for (const RankStatistics& r : problem.rank_statistics())
    out << "RANK rank=" << r.rank << " subdomains=" << r.subdomains << " primal=" << r.primal
        << " time_factor=" << r.time_factor << " time_solve=" << r.time_solve
        << " peak_memory_mb=" << r.peak_memory_mb << '\n';
  return out.str();
}

std::string format_report(const FetiProblem& problem, const FetiResult* result) {
  std::ostringstream out;
  out.precision(10);
  out << "variant=" << (problem.variant() == FetiVariant::feti1 ? "feti1" : "tfeti")
      << " path=" << path_name(problem.path())
      << " preconditioner=" << preconditioner_name(problem.dual().preconditioner_kind());
  if (result) out << " status_name=" << to_string(result->status) << " phases=" << result->phases;
  for (const auto& [key, value] : statistics(problem, result)) out << ' ' << key << '=' << value;
  if (result && result->friction_iterations > 0) out << " friction_hessian=" << friction_counts(*result);
  return out.str();
}

}  // namespace ffeti

#include "feti/feti_problem.h"

#include "feti/held_bytes.h"

#include "constraints/surface_checks.h"

#include "factor/blas_library.h"
#include "factor/lower_triangle.h"
#include "feti/dirichlet.h"
#include "base/errors.h"
#include "base/parallel_for.h"
#include "constraints/input_checks.h"
#include "feti/kernel.h"
#include "base/stopwatch.h"
#include "parallel/process.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace ffeti {
namespace {

/// Each distinct K_s replaced by its lower triangle, once for the subdomains that share it:
/// past the input checks (which walk full columns) every reader takes K_s's lower triangle,
/// and the full copy, the plugin's largest after the factors, goes before they come.
void keep_lower_triangles(std::vector<SubdomainInput>& inputs) {
  std::unordered_map<const SparseMatrix*, SharedMatrix> lower;  // by the full matrix, still held while looked up
  for (SubdomainInput& in : inputs) {
    const auto [at, first] = lower.try_emplace(&in.K.get());
    if (first) at->second = SharedMatrix(lower_triangle(in.K), in.K.name());
    in.K = at->second;
  }
}

}  // namespace

FetiProblem::FetiProblem(std::vector<SubdomainInput> subdomains, const ContactInput& contact,
                         const FetiSetupSettings& settings)
    : settings_(settings), comm_(std::make_shared<SerialCommunicator>()), inputs_(std::move(subdomains)) {
  global_count_ = static_cast<int>(inputs_.size());
  for (int s = 0; s < global_count_; ++s) global_ids_.push_back(s);
  set_up(contact);
}

FetiProblem::FetiProblem(std::vector<SubdomainInput> local, std::vector<int> global_ids, int global_count,
                         const ContactInput& local_contact, const FetiSetupSettings& settings,
                         std::shared_ptr<const Communicator> comm)
    : settings_(settings), comm_(std::move(comm)), inputs_(std::move(local)),
      global_ids_(std::move(global_ids)), global_count_(global_count) {
  set_up(local_contact);
}

void FetiProblem::set_up(const ContactInput& local_contact) {
  // Debian's serial OpenBLAS is not safe to call from concurrent threads (observed: spurious
  // "not positive definite" failures): supernodal factors, which call it, then run on one
  // thread, and an automatic choice with more threads stays simplicial. The reference BLAS
  // and OpenMP OpenBLAS gave bitwise the same solves from two threads at once
  // (scripts/factor_kinds.py); OpenBLAS's threaded builds lock their own state.
  if (loaded_blas() == BlasLibrary::openblas_sequential) {
    if (settings_.factor == FactorKind::supernodal) settings_.threads = 1;
    if (settings_.factor == FactorKind::automatic && resolve_thread_count(settings_.threads) > 1)
      settings_.factor = FactorKind::simplicial;
  }
  const ThreadLimit limit(settings_.threads);
  const Communicator& comm = *comm_;
  Stopwatch constraints_clock;
  // The problem's dimension from every rank's subdomains: a rank holding none still checks
  // the contact input (an obstacle's z entries) as a solid problem's.
  const auto has = [&](bool solid) {
    return std::any_of(inputs_.begin(), inputs_.end(), [&](const SubdomainInput& s) { return s.z.empty() != solid; });
  };
  const bool some_plane = comm.max(has(false) ? 1.0 : 0.0) > 0, some_solid = comm.max(has(true) ? 1.0 : 0.0) > 0;
  ContactInput dimensioned = local_contact;
  dimensioned.three_d = some_solid;
  collectively(comm, [&] {
    if (global_count_ < 1) throw InputError("K: no subdomains given");
    if (global_ids_.size() != inputs_.size()) throw InputError("K: one global index per local subdomain needed");
    for (size_t k = 0; k < global_ids_.size(); ++k)
      if (global_ids_[k] < 0 || global_ids_[k] >= global_count_ || (k > 0 && global_ids_[k] <= global_ids_[k - 1]))
        throw InputError("K: local subdomains need ascending global indices in 0.." + std::to_string(global_count_ - 1));
    validate_input(inputs_, dimensioned, global_ids_);
  });
  // validate_input compares a rank's own subdomains; a plane and a solid rank must not mix.
  if (some_plane && some_solid)
    throw InputError("Z: given for the subdomains of some ranks and missing for those of others: every subdomain of a "
                     "problem is plane or every one has a third coordinate");
  // The obstacle's side is judged from the slaves of all ranks (a body's slaves may be split).
  const ObstacleFacing facing = obstacle_facing(inputs_, local_contact);
  if (obstacle_points_into_bodies({comm.sum(facing.toward), comm.sum(facing.total)}))
    throw InputError("obstacle: its normal points into the bodies (the slave nodes' bodies lie on the side it points "
                     "to, read from K): give the normal pointing away from the obstacle, toward the bodies");
  collectively(comm, [&] { keep_lower_triangles(inputs_); });  // out of memory on one rank fails every rank

  // Who holds what: boxes, bodies and owners of all subdomains on every rank.
  std::vector<double> mine;
  for (size_t k = 0; k < inputs_.size(); ++k) {
    const BoundingBox b = bounding_box(inputs_[k]);
    mine.insert(mine.end(), {double(global_ids_[k]), double(inputs_[k].body), b.x0, b.y0, b.x1, b.y1, b.z0, b.z1,
                             inputs_[k].z.empty() ? 2.0 : 3.0});
  }
  std::vector<int> counts;
  const std::vector<double> all = comm.allgather(mine, &counts);
  std::vector<BoundingBox> boxes(static_cast<size_t>(global_count_));
  std::vector<int>& bodies = bodies_;
  std::vector<int>& owner = owner_;
  bodies.assign(static_cast<size_t>(global_count_), 0), owner.assign(static_cast<size_t>(global_count_), -1);
  std::string ownership_error;
  for (size_t r = 0, p = 0; r < counts.size(); ++r)
    for (int end = static_cast<int>(p) + counts[r]; static_cast<int>(p) < end; p += 9) {
      const auto s = static_cast<size_t>(all[p]);
      if (owner[s] >= 0) ownership_error = "K[" + std::to_string(s) + "]: given by two ranks";
      owner[s] = static_cast<int>(r);
      bodies[s] = static_cast<int>(all[p + 1]);
      boxes[s] = {all[p + 2], all[p + 3], all[p + 4], all[p + 5], all[p + 6], all[p + 7]};
      if (all[p + 8] != all[8])  // ranks' local checks see their own subdomains only
        ownership_error = "Z[" + std::to_string(s) + "]: " + (all[p + 8] == 3 ? "given" : "missing") + " where Z[" +
                          std::to_string(static_cast<int>(all[0])) + "] is " + (all[8] == 3 ? "given" : "missing") +
                          ": every subdomain of a problem is plane or every one has a third coordinate";
    }
  for (size_t s = 0; s < owner.size(); ++s)
    if (owner[s] < 0) ownership_error = "K[" + std::to_string(s) + "]: given by no rank";
  if (!ownership_error.empty()) throw InputError(ownership_error);  // the same on every rank
  space_dimension_ = static_cast<int>(all[8]);

  snap_ = snapping_length(boxes);
  boxes_ = std::move(boxes);
  local_contact_ = local_contact;
  local_contact_.three_d = space_dimension_ == 3;
  std::vector<DofRecord> slaves;
  Constraints constraints = build_rows(&slaves);
  if (local_contact.has_friction() && constraints.contact_rows() == 0)  // the rows are global: every rank alike
    throw InputError(std::string(local_contact.slip_bound >= 0 ? "slipBound" : "friction") +
                     ": given, but the problem has no contact rows to carry friction (no contactSlave, "
                     "contactSlaveFaces or obstacle pair)");
  built_rhs_ = rhs_ = Eigen::Map<const Vec>(constraints.rhs.data(), constraints.rows());
  if (local_contact.slip_bound >= 0)  // Tresca: the bounds per friction row are fixed at set-up
    friction_ = {true, Eigen::Map<const Vec>(constraints.slip_bound.data(), constraints.friction_rows)};
  sort_by_subdomain_and_dof(slaves);
  for (const auto& row : constraints.geometry) {
    const std::pair<int, int> slave_dof{row->slave_dof()[0], row->slave_dof()[1]};
    const auto it = std::lower_bound(slaves.begin(), slaves.end(), slave_dof, [](const DofRecord& r, const std::pair<int, int>& key) {
      return std::make_pair(r.subdomain, r.dof) < key;
    });
    if (it == slaves.end() || std::make_pair(it->subdomain, it->dof) != slave_dof)
      throw std::logic_error("set_up: a contact row's slave dof has no slave record");
    contact_positions_.push_back({it->x, it->y});
    contact_heights_.push_back(it->z);
    contact_body_component_.push_back({it->body, it->component});
  }
  setup_times_.constraints = constraints_clock.seconds();

  Stopwatch factor_clock;
  factorize(constraints);
  setup_times_.factorization = local_factor_seconds_ = factor_clock.seconds();
  collectively(comm, [&] {  // a rank out of memory fails every rank alike
    explicit_blocks_ = form_explicit_blocks(subdomains_, settings_.dual_operator, resolve_thread_count(settings_.threads));
  });
  explicit_blocks_ = {static_cast<long>(comm.sum(static_cast<double>(explicit_blocks_.subdomains))),
                      comm.max(explicit_blocks_.seconds)};
  explicit_bytes_ = comm.sum(explicit_block_bytes(subdomains_));

  Stopwatch coarse_clock;
  try {
    dual_ = std::make_unique<DualSystem>(subdomains_, global_ids_, owner, bodies, std::move(constraints),
                                         settings_.threads, comm, settings_.coarse_gram);
  } catch (const InputError& error) {  // thrown on every rank alike: the coarse space is global
    if (!local_contact.has_friction()) throw;
    throw InputError(std::string(error.what()) +
                     "; friction holds only where its coefficient or bound is > 0 (friction=0, slipBound=0 or a zero "
                     "of frictionField or slipBoundField where read gives a row no friction row)");
  }
  (dual_->coarse() ? setup_times_.coarse_space : setup_times_.constraints) += coarse_clock.seconds();
  if (settings_.conjugate_projector) {
    if (dual_->coarse())
      throw InputError("projector: \"conjugate\" is for problems where nothing floats (a time step's K + c M); this "
                       "one has a coarse space, which holds the floating subdomains' rigid modes already");
    Stopwatch projector_clock;
    std::vector<Eigen::MatrixXd> modes;
    for (const SubdomainInput& in : inputs_) modes.push_back(candidate_kernel(in.x, in.y, in.component, in.z));
    dual_->use_conjugate_projector(modes);
    setup_times_.coarse_space += projector_clock.seconds();
  }
  if (settings_.preconditioner != DualPreconditioner::none) {
    Stopwatch preconditioner_clock;
    precondition(*dual_, settings_.preconditioner);
    setup_times_.factorization += preconditioner_clock.seconds();
  }
  compute_dual_data();

  long local_primal = 0;
  double local_nonzeros = 0, local_bytes = 0, local_operator_bytes = 0, local_flops = 0;
  for (size_t k = 0; k < inputs_.size(); ++k) local_primal += inputs_[k].K.rows();
  std::unordered_set<const CholmodFactor*> counted;  // a factor shared by identical subdomains counts once
  for (const auto& s : subdomains_)
    if (counted.insert(&s->factor()).second)
      local_nonzeros += s->factor_nonzeros(), local_bytes += s->factor_bytes(), local_operator_bytes += s->operator_bytes(),
      local_flops += s->factor().analysis_flops();
  primal_dimension_ = static_cast<long>(comm.sum(static_cast<double>(local_primal)));
  input_bytes_ = comm.sum(ffeti::input_bytes(inputs_));
  kernel_bytes_ = comm.sum(ffeti::kernel_bytes(subdomains_));
  const DualSystem::HeldBytes dual_bytes = dual_->held_bytes();
  dual_bytes_ = {comm.sum(dual_bytes.rows), comm.sum(dual_bytes.coarse), comm.sum(dual_bytes.preconditioner)};
  factor_nonzeros_ = comm.sum(local_nonzeros);
  factor_bytes_ = comm.sum(local_bytes);
  operator_bytes_ = comm.sum(local_operator_bytes);
  factor_flops_ = comm.sum(local_flops);
  gather_rank_statistics(0.0);
  setup_times_ = {comm.max(setup_times_.constraints), comm.max(setup_times_.factorization),
                  comm.max(setup_times_.coarse_space), comm.max(setup_times_.dual_data), 0, 0, 0, 0};
}

void FetiProblem::precondition(DualSystem& system, DualPreconditioner kind) const {
  // The K the dual operator sees, copied only where FETI-1 eliminates Dirichlet dofs (a
  // copy of every K cost as much as the lumped preconditioner's whole set-up).
  std::vector<SparseMatrix> eliminated;
  eliminated.reserve(inputs_.size());  // the pointers below stay valid
  std::vector<const SparseMatrix*> operator_matrices;
  for (const SubdomainInput& in : inputs_) {
    if (settings_.variant == FetiVariant::feti1 && !in.dirichlet_dofs.empty()) {
      eliminated.push_back(eliminate_dirichlet(in.K, in.dirichlet_dofs));
      operator_matrices.push_back(&eliminated.back());
    } else {
      operator_matrices.push_back(&in.K.get());
    }
  }
  // A rank's failure (a K_ii not positive definite) fails every rank: none waits on it later.
  collectively(*comm_, [&] {
    system.use_preconditioner(kind, operator_matrices, settings_.threads, settings_.share_factors, settings_.scaling);
  });
}

Constraints FetiProblem::build_rows(std::vector<DofRecord>* gathered) const {
  const Communicator& comm = *comm_;
  std::vector<DofRecord> records = constraint_candidates(inputs_, global_ids_, local_contact_, boxes_, bodies_, snap_);
  // One rank holds every record already (packing a million interface records cost 0.15 s).
  if (comm.size() > 1) records = unpack(comm.allgather(pack(records)));
  const std::vector<SegmentRecord> segments =
      unpack_segments(comm.allgather(pack(segment_records(inputs_, global_ids_, local_contact_))));
  const std::vector<FaceRecord> faces =
      unpack_faces(comm.allgather(pack(face_records(inputs_, global_ids_, local_contact_))));
  if (gathered)  // the contact rows' positions are read from their slaves' records only
    std::copy_if(records.begin(), records.end(), std::back_inserter(*gathered), [](const DofRecord& r) { return r.slave; });
  return build_constraints(std::move(records), segments, faces, local_contact_, settings_.variant, snap_);
}

void FetiProblem::factorize(const Constraints& constraints) {
  const long before = CholmodFactor::factorizations_in_process();
  std::vector<Eigen::Index> sizes;
  for (const SubdomainInput& in : inputs_) sizes.push_back(in.K.rows());
  const std::vector<LocalConstraints> local = split_by_subdomain(constraints, sizes, global_ids_);
  const bool eliminate = settings_.variant == FetiVariant::feti1;
  const int count = local_subdomain_count();
  subdomains_.resize(inputs_.size());
  SharedAnalyses shared;  // boxes of one shape order and analyze once
  // The FETI-1 operators with Dirichlet dofs eliminated, kept while shared_factors compares
  // matrices by reference (declared first: destroyed after it).
  std::vector<SparseMatrix> eliminated(inputs_.size());
  SharedFactors shared_factors;  // boxes of one matrix factorize once
  collectively(*comm_, [&] {  // a failing subdomain fails the set-up on every rank alike
    parallel_for_each(count, resolve_thread_count(settings_.threads), [&](int k) {
      const SubdomainInput& in = inputs_[static_cast<size_t>(k)];
      const bool eliminates = eliminate && !in.dirichlet_dofs.empty();
      if (eliminates) eliminated[static_cast<size_t>(k)] = eliminate_dirichlet(in.K, in.dirichlet_dofs);
      subdomains_[static_cast<size_t>(k)] = std::make_unique<Subdomain>(
          global_ids_[static_cast<size_t>(k)], eliminates ? eliminated[static_cast<size_t>(k)] : in.K.get(),
          candidate_kernel(in.x, in.y, in.component, in.z), settings_.factor, settings_.ordering, &shared,
          touched_dofs(local[static_cast<size_t>(k)].B), settings_.share_factors ? &shared_factors : nullptr);
    });
  });
  factorizations_ = static_cast<long>(comm_->sum(double(CholmodFactor::factorizations_in_process() - before)));
  shared_factors_ = static_cast<long>(comm_->sum(static_cast<double>(shared_factors.reused())));
  const auto supernodal = std::count_if(subdomains_.begin(), subdomains_.end(), [](const auto& s) { return s->supernodal(); });
  supernodal_factors_ = static_cast<long>(comm_->sum(static_cast<double>(supernodal)));
  const auto on_interface =
      std::count_if(subdomains_.begin(), subdomains_.end(), [](const auto& s) { return s->interface_solves(); });
  interface_factors_ = static_cast<long>(comm_->sum(static_cast<double>(on_interface)));
  symbolic_analyses_ = static_cast<long>(comm_->sum(static_cast<double>(shared.analyses())));
}

void FetiProblem::gather_rank_statistics(double solve_seconds) const {
  long primal = 0;
  for (const auto& in : inputs_) primal += in.K.rows();
  const std::vector<double> all = comm_->allgather(std::vector<double>{
      double(local_subdomain_count()), double(primal), local_factor_seconds_, solve_seconds, peak_memory_mb()});
  rank_statistics_.clear();
  for (size_t p = 0; p + 5 <= all.size(); p += 5)
    rank_statistics_.push_back({static_cast<int>(p / 5), static_cast<int>(all[p]), static_cast<long>(all[p + 1]),
                                all[p + 2], all[p + 3], all[p + 4]});
}

void FetiProblem::set_loads(const std::vector<Vec>& loads) {
  const ThreadLimit limit(settings_.threads);
  collectively(*comm_, [&] {
    if (loads.size() != inputs_.size())
      throw InputError("F: has " + std::to_string(loads.size()) + " entries for " +
                       std::to_string(inputs_.size()) + " subdomains");
    for (size_t k = 0; k < loads.size(); ++k)
      if (loads[k].size() != inputs_[k].K.rows() || !loads[k].allFinite())
        throw InputError("F[" + std::to_string(global_ids_[k]) + "]: needs " +
                         std::to_string(inputs_[k].K.rows()) + " finite entries");
  });
  for (size_t k = 0; k < loads.size(); ++k) inputs_[k].f = loads[k];
  compute_dual_data();
}

std::vector<Vec> FetiProblem::operator_loads(const std::vector<Vec>& loads, bool homogeneous) const {
  std::vector<Vec> result;
  for (size_t k = 0; k < inputs_.size(); ++k) {
    const SubdomainInput& in = inputs_[k];
    const bool eliminated = settings_.variant == FetiVariant::feti1 && !in.dirichlet_dofs.empty();
    result.push_back(eliminated ? eliminated_load(in.K, loads[k], in.dirichlet_dofs,
                                                  homogeneous ? std::vector<double>{} : in.dirichlet_values)
                                : loads[k]);
  }
  return result;
}

void FetiProblem::compute_dual_data() {
  Stopwatch clock;
  std::vector<Vec> loads;
  for (const auto& in : inputs_) loads.push_back(in.f);
  data_ = dual_->data(operator_loads(loads, false), rhs_);
  setup_times_.dual_data = clock.seconds();
}

void FetiProblem::set_dirichlet_values(const std::vector<std::vector<double>>& values) {
  collectively(*comm_, [&] {
    if (values.size() != inputs_.size())
      throw InputError("dirichletValues: has " + std::to_string(values.size()) + " entries for " +
                       std::to_string(inputs_.size()) + " subdomains");
    for (size_t k = 0; k < values.size(); ++k) {
      const std::string name = "dirichletValues[" + std::to_string(global_ids_[k]) + "]";
      if (values[k].size() != inputs_[k].dirichlet_dofs.size())
        throw InputError(name + ": needs one value per Dirichlet dof (" + std::to_string(inputs_[k].dirichlet_dofs.size()) +
                         " as at set-up), got " + std::to_string(values[k].size()));
      for (double v : values[k])
        if (!std::isfinite(v)) throw InputError(name + ": has a non-finite value");
    }
  });
  const ThreadLimit limit(settings_.threads);
  for (size_t k = 0; k < values.size(); ++k) inputs_[k].dirichlet_values = values[k];
  rebuild_right_hand_side();
}

void FetiProblem::set_contact_gaps(const std::vector<std::vector<double>>& gaps) {
  collectively(*comm_, [&] {
    if (gaps.size() != inputs_.size())
      throw InputError("contactGap: has " + std::to_string(gaps.size()) + " entries for " +
                       std::to_string(inputs_.size()) + " subdomains");
    validate_contact_gaps(gaps, inputs_, global_ids_);
  });
  const ThreadLimit limit(settings_.threads);
  local_contact_.gap_field = gaps;
  rebuild_right_hand_side();
}

void FetiProblem::rebuild_right_hand_side() {
  Constraints rebuilt;
  collectively(*comm_, [&] { rebuilt = build_rows(); });
  const Vec now = Eigen::Map<const Vec>(rebuilt.rhs.data(), rebuilt.rows());
  if (now.size() != rhs_.size()) throw std::logic_error("rebuild_right_hand_side: the same input built other rows");
  // Only load steps move c from its build, and only on the friction rows (their slip is
  // measured from the last step's state): the other rows take the new build as it is, so a
  // re-solve equals a fresh set-up's bit for bit; c is affine in the prescribed values and
  // gaps, so the friction rows take the build's change.
  const int first_friction = constraints().first_friction_row();
  rhs_.head(first_friction) = now.head(first_friction);
  rhs_.tail(rhs_.size() - first_friction) += now.tail(now.size() - first_friction) - built_rhs_.tail(now.size() - first_friction);
  built_rhs_ = now;
  dual_->replace_right_hand_side(std::move(rebuilt));
  compute_dual_data();
}

void FetiProblem::start_load_step(const FetiResult& last) {
  collectively(*comm_, [&] {
    // A state stopped at round-off (stagnated) is as accurate as its data allow: it starts
    // a step as a converged one does (a dynamic scene's steps, tests/edp/sliding-block).
    if (last.status != SolveStatus::converged && last.status != SolveStatus::stagnated)
      throw InputError("P: the last solve ended " + to_string(last.status) +
                       ", so its state cannot start the next load step (friction depends on the load path)");
  });
  if (!has_friction()) return;
  const ThreadLimit limit(settings_.threads);
  Vec Bu;
  dual_->F().apply_B(last.u, Bu);
  rhs_.tail(constraints().friction_rows) = Bu.tail(constraints().friction_rows);  // slip measured from here
  step_start_ = last.lambda;
  compute_dual_data();
}

FetiResult FetiProblem::solve(const DualSolveSettings& settings) const {
  const ThreadLimit limit(settings_.threads);
  FetiResult result;
  if (has_friction()) {
    FrictionSolution friction = solve_with_friction(*dual_, data_, friction_, settings, step_start_, bodies_);
    static_cast<DualSolution&>(result) = std::move(friction.dual);
    result.friction_iterations = friction.iterations;
    result.friction_hessian = std::move(friction.hessian);
    result.friction_bound_change = friction.bound_change;
    result.sliding_body = friction.sliding_body;
    result.newton_steps = friction.newton_steps;
    result.newton_hessian = friction.newton_hessian;
    result.slip_bound = std::move(friction.slip_bound);
    Vec Bu;
    dual_->F().apply_B(result.u, Bu);
    result.slip = Bu.tail(constraints().friction_rows) - rhs_.tail(constraints().friction_rows);
  } else {
    static_cast<DualSolution&>(result) = dual_->solve(data_, settings);
  }
  result.phases = "constraints,factorization";
  if (dual_->coarse()) result.phases += ",coarse_space";
  if (result.path != DualPath::cholesky) result.phases += ",dual_data";
  if (result.path == DualPath::mprgp || result.path == DualPath::smalbe) result.phases += ",norm_estimate";
  if (result.path != DualPath::cholesky) result.phases += std::string(",") + path_name(result.path);
  if (has_friction()) result.phases += ",friction";
  result.phases += ",recovery,kkt";

  Stopwatch kkt_clock;
  const Constraints& c = constraints();
  std::vector<Vec> loads;
  for (const auto& in : inputs_) loads.push_back(in.f);
  const bool eliminated = settings_.variant == FetiVariant::feti1;
  result.kkt = kkt_residuals(inputs_, loads, rhs_, false, dual_->local(), dual_->F(), c, eliminated, result.u,
                             result.lambda, *comm_, result.slip_bound);
  result.energy = energy(inputs_, result.u, *comm_);
  // Finite data can still overflow (a gap of -1e300, a point at 1e308): no answer with a
  // non-finite energy, residual or multiplier is reported as anything but an overflow.
  if (!std::isfinite(result.energy) || !result.kkt.finite() || !result.lambda.allFinite())
    result.status = SolveStatus::overflow;
  // The dual stop tests take K^+ as exact. A stiffness singular beyond the rigid modes its
  // kernel check found (e.g. a plane field whose rows have x and y swapped) slips through
  // with a tiny pivot, and the dual test then holds on an answer whose equilibrium fails
  // (relative residual 0.57 seen, against at most about tol on every scene): not converged.
  else if (result.status == SolveStatus::converged && result.kkt.equilibrium > std::max(1000 * settings.tolerance, 1e-6))
    result.status = SolveStatus::inaccurate;
  for (int i = c.equality_rows; i < c.rows(); ++i)
    if (c.kind[static_cast<size_t>(i)] == RowKind::contact && result.lambda[i] > 0) ++result.active_contact;
  result.beyond_reach = check_beyond_reach(c.beyond_reach, result.u, global_ids_, *comm_);
  if (has_friction())
    for (ContactState state : contact_row_forces(c, result.lambda, result.slip_bound, result.slip).state)
      result.slipping_contact += state == ContactState::slip ? 1 : 0;
  result.times.kkt = kkt_clock.seconds();
  gather_rank_statistics(result.times.norm_estimate + result.times.solve);
  PhaseTimes& t = result.times;  // the slowest rank's, by name (a positional list broke once a phase was added)
  for (double* phase : {&t.norm_estimate, &t.free_rows, &t.solve, &t.dual_operator, &t.preconditioner, &t.primal_checks, &t.recovery,
                         &t.kkt, &t.hessian, &t.factor_solves})
    *phase = comm_->max(*phase);
  return result;
}

}  // namespace ffeti

// One subdomain's operator: its stiffness K_s, kernel R_s and a generalized inverse K_s^+
// (K_s K_s^+ K_s = K_s) by "fixing dofs": K_s with r_s well-chosen dofs removed is regular.
#pragma once

#include "factor/cholmod_factor.h"
#include "factor/dense_interface_inverse.h"
#include "factor/shared_factors.h"

#include <Eigen/Dense>

#include <memory>
#include <vector>

namespace ffeti {

/// How the dual operator applies K_s^+ on a subdomain's interface: by the factor's solves
/// (`implicit`), by a dense block of K_s^+ on the interface formed once after the
/// factorization (`explicit_block`), or the latter where it reads fewer bytes
/// (`automatic`: explicit_inverse_pays).
enum class DualOperatorForm { implicit, explicit_block, automatic };

class Subdomain {
 public:
  /// Computes the kernel inside span(kernel_candidates), chooses the fixing dofs and
  /// factorizes. K is the operator the dual problem uses (for FETI-1 with the Dirichlet
  /// dofs eliminated). Throws InputError naming "K[index]" if the factorization fails or
  /// the generalized inverse does not verify. The object keeps the factor and the kernel.
  /// With `shared`, subdomains whose factorized block has one pattern share its analysis.
  /// `interface` (sorted dofs): where the constraint rows B_s touch the subdomain; the factor
  /// may order them last so that the dual operator solves on them alone. Only K's lower
  /// triangle is read (full storage reads the same).
  /// With `shared_factors`, subdomains of bitwise equal K, fixing dofs and interface share
  /// one factor (and the checks of its generalized inverse).
  Subdomain(int index, const SparseMatrix& K, const Eigen::MatrixXd& kernel_candidates, FactorKind factor_kind,
            InterfaceOrdering ordering = InterfaceOrdering::fill_reducing, SharedAnalyses* shared = nullptr,
            const std::vector<int>& interface = {}, SharedFactors* shared_factors = nullptr);

  Eigen::Index size() const { return size_; }
  /// Orthonormal basis of Ker K_s (n_s x r_s); r_s = 0 for a regular subdomain.
  const Eigen::MatrixXd& kernel() const { return R_; }
  bool floating() const { return R_.cols() > 0; }
  const std::vector<int>& fixing() const { return fixing_; }

  /// x = K_s^+ b: zeros at the fixing dofs, the regular block's solution elsewhere.
  /// Thread-safe across distinct subdomains (shared factors included), not on the same one.
  void apply_pseudo_inverse(const Vec& b, Vec& x) const;
  /// The same for every column of b, in one pass over the factor.
  void apply_pseudo_inverse(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) const;

  /// The interface dofs given at construction.
  const std::vector<int>& interface() const { return interface_; }
  /// True when apply_pseudo_inverse_on_interface is available (the factor ordered the
  /// interface last: CholmodFactor::factorize).
  bool interface_solves() const { return factor_->interface_solves(); }
  /// True when apply_pseudo_inverse_on_interface is available: interface solves, or an
  /// explicit block.
  bool solves_on_interface() const { return interface_solves() || explicit_block_ != nullptr; }
  /// (K_s^+ b) on the interface for b zero elsewhere; b and x are indexed like interface().
  /// The dual operator's solve: a product with the explicit block where one was formed,
  /// else a solve that reads only the factor's interface block.
  void apply_pseudo_inverse_on_interface(const Vec& b, Vec& x) const;
  /// The same for every column of b (with the explicit block: one pass over it).
  void apply_pseudo_inverse_on_interface(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) const;

  /// Forms the explicit block, K_s^+ restricted to the interface (zero on fixing dofs, the
  /// same generalized inverse the factor applies), where `form` asks for it: always with
  /// `explicit_block`, where explicit_inverse_pays with `automatic`. Needs an interface.
  /// Returns whether it formed one. Thread-safe across distinct subdomains.
  bool form_explicit_block(DualOperatorForm form);
  /// Takes the explicit block of `identical`, a subdomain that shares this one's factor
  /// (so the same K, fixing dofs and interface: SharedFactors), if it has one.
  void share_explicit_block(const Subdomain& identical);
  bool has_explicit_block() const { return explicit_block_ != nullptr; }
  /// The explicit block, or null (shared by identical subdomains: the same pointer).
  const PackedSymmetric* explicit_block() const { return explicit_block_.get(); }

  /// ||K K^+ K v - K v|| / ||K v|| for a fixed pseudo-random v, K the matrix this
  /// subdomain was built from (the check run at set-up).
  double pseudo_inverse_residual(const SparseMatrix& K) const;
  /// The factor of K_s (with its fixing dofs removed), possibly shared with identical subdomains.
  const CholmodFactor& factor() const { return *factor_; }
  double factor_nonzeros() const { return factor_->factor_nonzeros(); }
  double factor_bytes() const { return factor_->factor_bytes(); }
  /// The bytes one pass of the dual operator's solve reads: the explicit block's where one
  /// was formed (its product is the whole solve), else one triangular solve's of the factor
  /// (the interface block's with interface solves, else the whole factor's).
  double operator_bytes() const { return explicit_block_ ? explicit_block_->bytes() : factor_operator_bytes_; }
  bool supernodal() const { return factor_->supernodal(); }

 private:
  int index_;
  Eigen::Index size_;  // K itself is not kept: the factor and the kernel are all a solve needs
  Eigen::MatrixXd R_;
  std::vector<int> fixing_;
  std::vector<int> reduced_to_full_;  // dofs kept in the regular block
  std::vector<int> interface_;
  std::vector<int> interface_kept_;   // positions in interface_ that are not fixing dofs
  std::vector<int> interface_columns_;  // per interface dof its column of the factor, -1 at fixing dofs
  std::shared_ptr<const CholmodFactor> factor_;  // possibly shared with identical subdomains
  mutable CholmodSolveWorkspace workspace_;     // this subdomain's own: solves run concurrently
  double factor_operator_bytes_ = 0;
  std::shared_ptr<const PackedSymmetric> explicit_block_;  // possibly shared like the factor
  /// One column of apply_pseudo_inverse_on_interface by the factor's interface solve (x
  /// sized like the interface).
  void solve_interface_column(Eigen::Ref<const Vec> b, Eigen::Ref<Vec> x) const;

  mutable Vec reduced_rhs_, reduced_solution_, interface_rhs_, interface_solution_;
  mutable Eigen::MatrixXd reduced_block_rhs_, reduced_block_solution_;
};

/// Subdomains are built in parallel and hold non-movable factors: owned through pointers.
using SubdomainList = std::vector<std::unique_ptr<Subdomain>>;

/// What form_explicit_blocks did on this rank (their bytes: held_bytes.h).
struct ExplicitBlocks {
  long subdomains = 0;  ///< that hold an explicit block (shared ones included)
  double seconds = 0;   ///< wall-clock, forming them
};

/// Subdomain::form_explicit_block on every subdomain as `form` says, on `threads` threads,
/// each distinct factor's block formed once and shared by the subdomains of that factor.
/// Throws what a forming throws (out of memory) after all ran.
ExplicitBlocks form_explicit_blocks(SubdomainList& subdomains, DualOperatorForm form, int threads);

}  // namespace ffeti

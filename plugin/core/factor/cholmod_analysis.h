// The choices behind a CHOLMOD analysis: the fill-reducing ordering, supernodes, and the
// switch between simplicial and supernodal factors.
#pragma once

#include <cholmod.h>

namespace ffeti {

/// Flops per nonzero of L from which an automatic factor is supernodal (measured by
/// scripts/factor_kinds.py; docs/algorithms.md).
double supernodal_switch();

/// The project's settings on a fresh cholmod_common: the supernodal switch above, and
/// supernodes that hold no explicit zeros but CHOLMOD's always-merged smallest ones.
void set_analysis_choices(cholmod_common& common);

/// cholmod_analyze, one call at a time in the process (METIS's random state is global).
cholmod_factor* analyze_alone(cholmod_sparse* A, cholmod_common* common);

/// The least flops per column of CHOLMOD's own factorization at which analyze_fewest_entries
/// tries METIS too (measured: cholmod_analysis.cpp).
constexpr double kLeastFlopsPerColumnForMetis = 10000;

/// The analysis of A whose factor holds the fewest values: CHOLMOD's own choice and, for a
/// supernodal factor of at least kLeastFlopsPerColumnForMetis flops per column where CHOLMOD
/// did not call METIS itself, METIS's nested dissection beside it. Null if CHOLMOD's analysis
/// failed.
cholmod_factor* analyze_fewest_entries(cholmod_sparse* A, cholmod_common* common);

/// For the scope's cholmod_analyze calls: one ordering method, `ordering`; the factor kind
/// and the postorder the caller may set too. All four are restored as the scope ends.
class OneOrdering {
 public:
  OneOrdering(cholmod_common& common, int ordering)
      : common_(common), methods_(common.nmethods), ordering_(common.method[0].ordering),
        supernodal_(common.supernodal), postorder_(common.postorder) {
    common.nmethods = 1, common.method[0].ordering = ordering;
  }
  ~OneOrdering() {
    common_.nmethods = methods_, common_.method[0].ordering = ordering_;
    common_.supernodal = supernodal_, common_.postorder = postorder_;
  }
  OneOrdering(const OneOrdering&) = delete;
  OneOrdering& operator=(const OneOrdering&) = delete;

 private:
  cholmod_common& common_;
  const int methods_, ordering_, supernodal_, postorder_;
};

}  // namespace ffeti

#include "factor/cholmod_analysis.h"

#include <algorithm>
#include <iterator>
#include <mutex>

namespace ffeti {

double supernodal_switch() {
  // scripts/factor_kinds.py on this machine (loaded; docs/log.md, 2026-11-27), one thread,
  // under the reference BLAS and OpenMP OpenBLAS: simplicial faster at 41 (2D scalar, 4225
  // dofs) and 64 flops per nonzero (3D elasticity, 375 dofs); at 82 (2D elasticity, 8450
  // dofs) supernodal won 1.4 to 3.6 times under OpenBLAS but tied under the reference BLAS
  // in one of two runs, and its solves (one per Hessian multiplication) were up to 2 times
  // slower; from 137 (3D elasticity, 1029 dofs) up supernodal won under both. CHOLMOD's
  // own default is 40.
  return 120;
}

void set_analysis_choices(cholmod_common& common) {
  common.supernodal_switch = supernodal_switch();  // read by CHOLMOD_AUTO only
  // No relaxed amalgamation (zeros stored to make supernodes larger) beyond the small
  // supernodes CHOLMOD always merges: its zeros were 7 % of the real mesh's factor values,
  // and without them neither the factorization nor the solves got slower there or on the
  // 3D boxes (docs/log.md, 2026-12-07).
  std::fill(std::begin(common.zrelax), std::end(common.zrelax), 0.0);
}

// One at a time: the fill-reducing choice may call METIS, whose random generator (GKlib's)
// is global state: two orderings on two threads draw from one stream in whatever order the
// threads reach it, so the orderings, hence the factors' rounding and the iteration counts,
// changed from run to run (the sphere on the plane at h 0.07: 158 to 166 Hessian
// multiplications on two threads, 163 on one).
cholmod_factor* analyze_alone(cholmod_sparse* A, cholmod_common* common) {
  static std::mutex one_ordering;
  const std::lock_guard<std::mutex> lock(one_ordering);
  return cholmod_analyze(A, common);
}

// CHOLMOD's default tries AMD and calls METIS only where AMD's flops per entry pass 500 and
// its factor holds 5 times A's entries; 3D parts stay below that although METIS's nested
// dissection stores fewer values on them: 14 % fewer on the real mesh's parts of 1000 nodes
// (crowned-punch-3d.edp -h 0.5; docs/log.md, 2026-12-07). The threshold on flops per column:
// the METIS call took 2.5-3.3 us per column on 2D and 3D patterns alike; 3D parts (the real
// mesh's of 500 to 3500 nodes, the boxes) factor at 19,000 to 250,000 flops per column and
// METIS stored up to 22 % fewer values; 2D subdomains stay near 5,000 (H/h = 256: 66k
// columns), where METIS stored 1 % more and its call added 2 s to a 1 s factorization phase.
cholmod_factor* analyze_fewest_entries(cholmod_sparse* A, cholmod_common* common) {
  cholmod_factor* chosen = analyze_alone(A, common);
  if (!chosen || !chosen->is_super || common->called_nd ||
      common->fl < kLeastFlopsPerColumnForMetis * static_cast<double>(A->ncol))
    return chosen;
  const double flops = common->fl, nonzeros = common->lnz;
  const int status = common->status;
  cholmod_factor* dissected = nullptr;
  {
    const OneOrdering metis(*common, CHOLMOD_METIS);
    dissected = analyze_alone(A, common);
  }
  if (dissected && dissected->is_super && dissected->xsize < chosen->xsize) {
    cholmod_free_factor(&chosen, common);
    return dissected;
  }
  cholmod_free_factor(&dissected, common);
  common->fl = flops, common->lnz = nonzeros, common->status = status;  // the kept analysis's
  return chosen;
}

}  // namespace ffeti

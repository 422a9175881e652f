// The numeric supernodal Cholesky factorization on CHOLMOD's symbolic analysis, its dense
// blocks through Eigen's kernels.
//
// CHOLMOD's own (cholmod_factorize on a supernodal analysis) runs each supernode's updates
// and its dense Cholesky through the BLAS; with the reference BLAS the set-up installs
// (docs/dependencies.md) they run at about 5 GFlop/s on this project's machines, Eigen's
// at about 15 (docs/log.md, 2026-11-28). The analysis (ordering, supernodes, their rows)
// stays CHOLMOD's; this fills the same L->x, left-looking as CHOLMOD does: each supernode
// gathers its columns of A, subtracts the updates of the supernodes below it in the
// elimination tree that reach its columns, factors its diagonal block and solves for the
// rows below it.
#pragma once

#include <cholmod.h>

namespace ffeti {

/// Fills L (a supernodal factor with its analysis done and its values allocated:
/// L.xtype == CHOLMOD_REAL) with the Cholesky factor of P A P', A given by its lower
/// triangle (`lower`: CHOLMOD's view of a symmetric matrix, stype -1, entries above the
/// diagonal ignored). Returns true on success, false where a diagonal block is not
/// positive definite (L's values are then unspecified). Runs on the calling thread's OpenMP
/// limit: callers outside a parallel region limit it to one thread (CholmodFactor), so that
/// the factor does not depend on the thread count (Eigen's product blocking does).
bool supernodal_factorize(const cholmod_sparse& lower, cholmod_factor& L);

}  // namespace ffeti

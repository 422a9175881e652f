// Settling a given start before MPRGP: inexact steps of the primal-dual active set method
// that only release bounds.
#pragma once

#include "qp/problem.h"

namespace ffeti {

/// Up to `rounds` face solves from the feasible start x, with g = Ax - b on entry. Each
/// round runs conjugate gradients on the start's free set (the other components held at
/// their bounds, the bounds themselves ignored; directions from M restricted to that set)
/// until the free gradient has fallen by 100 or after 30 steps, then projects x onto the
/// bounds. A round is kept only if it lowers f(x) = 1/2 x'Ax - b'x; the rounds end at the
/// first that projects nothing, is not kept, or would pass `max_hessian` multiplications.
/// On return x is feasible and g = Ax - b at it. CG steps go to counts.settle, every
/// multiplication to counts.hessian, M's applications to counts.preconditioner; the monitor
/// gets a "settle" line after each kept round.
///
/// Why: a start carried over from a coarser mesh or a nearby problem has nearly the right
/// contact set but not the forces on it. MPRGP started there takes CG steps whose transient
/// pushes multipliers across their bounds; its expansions release those couples and its
/// proportioning takes them back, swinging several times (docs/results/large-contact-reading.md).
/// Solving the start's face first makes the forces consistent with the set, so what
/// projection releases is only where the start's set was wrong.
void settle_start(const LinearOperator& A, const Vec& b, const qp::ConstraintSet& bounds, int rounds, int max_hessian,
                  Vec& x, Vec& g, IterationCounts& counts, const LinearOperator& preconditioner = {},
                  const Monitor& monitor = {});

}  // namespace ffeti

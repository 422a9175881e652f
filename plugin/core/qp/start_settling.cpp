#include "qp/start_settling.h"

#include "qp/constraint_set.h"

#include <vector>

namespace ffeti {
namespace {

// With two rounds (DualSolveSettings::settle). One round to 1e-3 was measured too: better on
// the large contact zone's fixed 9-subdomain split (37, 45, 85 multiplications at n = 80 ..
// 320 against 41, 56, 90), worse at fixed H/h (39, 52, 38 against 29, 36, 32).
constexpr double kFaceGradientReduction = 1e-2;
constexpr int kFaceSteps = 30;

/// v on the face (mask true), 0 elsewhere.
void restrict_to_face(const std::vector<char>& face, Vec& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!face[i]) v[i] = 0.0;
}

/// One face solve from y (gradient gy) by conjugate gradients on `face`; it stops early on a
/// direction of nonpositive curvature, y and gy consistent at every step. Not
/// conjugate_gradient(): it multiplies once to form the start's gradient (known here) and once
/// more to verify the final one on the face, where the caller needs the whole gradient after
/// projection; two of the 10 to 20 multiplications a round takes.
void solve_on_face(const LinearOperator& A, const std::vector<char>& face, int max_hessian, Vec& y, Vec& gy,
                   IterationCounts& counts, const LinearOperator& preconditioner) {
  Vec r = gy, z, p, Ap;
  restrict_to_face(face, r);
  const auto precondition = [&] {
    if (!preconditioner) {
      z = r;
      return;
    }
    preconditioner(r, z);
    ++counts.preconditioner;
    restrict_to_face(face, z);
  };
  const double target = kFaceGradientReduction * r.norm();
  precondition();
  p = z;
  double rz = r.dot(z);
  for (int step = 0; step < kFaceSteps && r.norm() > target && counts.hessian < max_hessian; ++step) {
    A(p, Ap);
    ++counts.hessian;
    const double pAp = p.dot(Ap);
    if (!(pAp > 0)) return;
    const double alpha = rz / pAp;
    y -= alpha * p;
    gy -= alpha * Ap;
    r = gy;
    restrict_to_face(face, r);
    precondition();
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
    ++counts.settle;
  }
}

}  // namespace

void settle_start(const LinearOperator& A, const Vec& b, const qp::ConstraintSet& bounds, int rounds, int max_hessian,
                  Vec& x, Vec& g, IterationCounts& counts, const LinearOperator& preconditioner,
                  const Monitor& monitor) {
  std::vector<char> face;
  Vec y, gy, Ay;
  for (int round = 0; round < rounds && counts.hessian + 1 < max_hessian; ++round) {
    face = bounds.free_components(x);
    y = x;
    gy = g;
    solve_on_face(A, face, max_hessian - 1, y, gy, counts, preconditioner);
    const int released = bounds.project(y);
    if (released > 0) {
      A(y, Ay);
      ++counts.hessian;
      gy = Ay - b;
    }
    if (!(0.5 * y.dot(gy - b) < 0.5 * x.dot(g - b))) return;
    x.swap(y);
    g.swap(gy);
    if (monitor)
      monitor({"settle", round, bounds.projected_gradient(x, g).norm(), 0.0, counts.hessian, bounds.off_bound_count(x)});
    if (released == 0) return;
  }
}

}  // namespace ffeti

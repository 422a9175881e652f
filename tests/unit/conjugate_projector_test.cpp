// The conjugate projector (projector = "conjugate") on the seed's membranes made a time
// step: K + c I, which no subdomain's kernel survives, so nothing floats and the dual
// problem runs on the MPRGP path. With a small c (a long step) the floating body's rigid
// motion is held only by c: F is ill-conditioned in it, and the projector onto the
// subdomains' rigid modes on the gluing rows takes that direction out of the iteration.
// The answer must be the same, in fewer multiplications; a problem with a coarse space
// refuses the option.
#include "feti/feti_problem.h"
#include "input_error.h"
#include "membrane_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ffeti {
namespace {

/// The membranes with c times the identity added to every subdomain's K (a lumped unit
/// mass over a step of 2 / sqrt(c)).
std::vector<SubdomainInput> stepped_membranes(double c) {
  auto subs = test::membrane_subdomains(test::membrane_options(32, 4));
  for (SubdomainInput& s : subs) {
    SparseMatrix& K = s.K.edit();
    for (Eigen::Index i = 0; i < K.rows(); ++i) K.coeffRef(i, i) += c;
  }
  return subs;
}

FetiResult solve(std::vector<SubdomainInput> subs, bool projector) {
  const ContactInput contact = test::membrane_contact(subs);
  FetiSetupSettings setup;
  setup.conjugate_projector = projector;
  DualSolveSettings settings = test::tight();
  settings.tolerance = 1e-10;
  return FetiProblem(std::move(subs), contact, setup).solve(settings);
}

TEST(ConjugateProjector, SameAnswerInFewerMultiplicationsWhereTheStepIsLong) {
  for (const double c : {1e-4, 1e-2}) {
    const FetiResult plain = solve(stepped_membranes(c), false);
    const FetiResult projected = solve(stepped_membranes(c), true);
    ASSERT_EQ(plain.status, SolveStatus::converged) << "c = " << c;
    ASSERT_EQ(projected.status, SolveStatus::converged) << "c = " << c;
    EXPECT_EQ(plain.path, DualPath::mprgp);
    EXPECT_NEAR(projected.energy, plain.energy, 1e-8 * std::abs(plain.energy)) << "c = " << c;
    double difference = 0, size = 0;
    for (size_t s = 0; s < plain.u.size(); ++s) {
      difference = std::max(difference, (projected.u[s] - plain.u[s]).lpNorm<Eigen::Infinity>());
      size = std::max(size, plain.u[s].lpNorm<Eigen::Infinity>());
    }
    EXPECT_LT(difference, 1e-7 * size) << "c = " << c;
    EXPECT_LT(projected.counts.hessian, plain.counts.hessian) << "c = " << c;
    EXPECT_LT(projected.kkt.max(), 1e-8) << "c = " << c;
  }
}

TEST(ConjugateProjector, AProblemWithACoarseSpaceRefusesIt) {
  auto subs = test::membrane_subdomains(test::membrane_options(16, 2));
  const ContactInput contact = test::membrane_contact(subs);
  FetiSetupSettings setup;
  setup.conjugate_projector = true;
  expect_input_error([&] { FetiProblem(std::move(subs), contact, setup); }, "projector: \"conjugate\" is for problems");
}

}  // namespace
}  // namespace ffeti

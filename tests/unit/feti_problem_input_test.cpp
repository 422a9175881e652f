// FetiProblem's refusals of bad input (each names its argument) and the thread count's
// default.
#include "feti/coarse_space.h"
#include "constraints/contact/obstacle.h"
#include "feti/dual_operator.h"
#include "base/errors.h"
#include "feti/feti_problem.h"
#include "feti/kernel.h"
#include "service/options.h"
#include "feti/primal.h"
#include "parallel/process.h"
#include "membrane_model.h"
#include "input_error.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numeric>

namespace ffeti {
namespace {

using test::membrane_problem;

TEST(FetiProblem, BadInputIsAnErrorNamingTheArgument) {
  const auto make = [](const std::function<void(std::vector<SubdomainInput>&)>& spoil) {
    auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
    const ContactInput contact = test::membrane_contact(subs);
    spoil(subs);
    FetiProblem problem(std::move(subs), contact);
  };
  const FetiProblem problem = membrane_problem(test::membrane_options(8, 2), FetiVariant::feti1);
  DualSolveSettings wrong_start;
  wrong_start.start = Vec::Zero(problem.constraints().rows() + 1);
  expect_input_error([&] { problem.solve(wrong_start); }, "start: has");
  wrong_start.start = Vec::Zero(problem.constraints().rows());
  wrong_start.start[0] = NAN;
  expect_input_error([&] { problem.solve(wrong_start); }, "start: has entries that are not finite");
  expect_input_error([&] { make([](auto& s) { s[2].K.edit().coeffRef(0, 1) += 1.0; }); }, "K[2]: not symmetric");
  // An entry whose mirror is not stored at all, above and below the diagonal.
  expect_input_error([&] { make([](auto& s) { s[2].K.edit().coeffRef(0, s[2].K.cols() - 1) = 1.0; }); }, "K[2]: not symmetric");
  expect_input_error([&] { make([](auto& s) { s[1].K.edit().coeffRef(s[1].K.rows() - 1, 0) = 1.0; }); }, "K[1]: not symmetric");
  // Checked on threads, named as a serial loop would: the lowest bad subdomain.
  expect_input_error([&] {
    make([](auto& s) {
      s[3].K.edit().coeffRef(0, 1) += 1.0;
      s[1].f[0] = NAN;
    });
  }, "F[1]");
  expect_input_error([&] { make([](auto& s) { s[1].f.conservativeResize(3); }); }, "F[1]");
  expect_input_error([&] { make([](auto& s) { s[3].f[0] = NAN; }); }, "F[3]");
  expect_input_error([&] { make([](auto& s) { s[0].K.edit().coeffRef(0, 0) = INFINITY; }); }, "K[0]");
  expect_input_error([&] { make([](auto& s) { s[1].x.pop_back(); }); }, "X[1]");
  expect_input_error([&] { make([](auto& s) { s[0].dirichlet_dofs.push_back(100000); }); }, "dirichlet[0]");
  expect_input_error([&] { make([](auto& s) { s[2].y[5] = NAN; }); }, "X[2], Y[2]: the coordinates of dof 5");
  expect_input_error([&] { make([](auto& s) { s[3].body = -1; }); }, "body[3]");
  expect_input_error([&] {
    make([](auto& s) {
      s[0].dirichlet_values.assign(s[0].dirichlet_dofs.size(), 0.0);
      s[0].dirichlet_values[1] = NAN;
    });
  }, "dirichletValues[0]: entry 1");
  // A floating body with no condition at all: its rigid mode is unrestrained.
  expect_input_error([] {
    auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
    FetiProblem problem(std::move(subs), ContactInput{});
  }, "body 1");
  // Node-to-node partners and an obstacle for the same slaves: ambiguous, refused.
  expect_input_error([] {
    auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
    ContactInput contact = test::membrane_contact(subs);
    contact.input_of<ObstacleInput>().given = true;
    FetiProblem problem(std::move(subs), contact);
  }, "contactMaster");
  // Positive diagonal but indefinite (a large symmetric off-diagonal pair between free
  // dofs), in a subdomain touching the Dirichlet boundary and in a floating one: the
  // simplicial LDL' factor would complete with a negative D and the solve find a saddle
  // point; it must be an error naming K[s].
  for (int s : {0, 5})
    for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti})
      expect_input_error([&] {
        auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
        const ContactInput contact = test::membrane_contact(subs);
        const double d = subs[static_cast<size_t>(s)].K.get().coeff(12, 12);
        subs[static_cast<size_t>(s)].K.edit().coeffRef(12, 13) += 5 * d;
        subs[static_cast<size_t>(s)].K.edit().coeffRef(13, 12) += 5 * d;
        FetiSetupSettings setup;
        setup.variant = variant;
        FetiProblem problem(std::move(subs), contact, setup);
      }, "K[" + std::to_string(s) + "]: not positive definite");
  DualSolveSettings bad;
  bad.tolerance = 0;
  expect_input_error([&] { membrane_problem(test::membrane_options(8, 1), FetiVariant::feti1).solve(bad); }, "tol");
}

}  // namespace

TEST(Threads, TheDefaultLeavesBusyCoresToOthersAndAnExplicitCountAlone) {
  // Between 1 and the cores asked for, whatever the machine's load now.
  const int adapted = threads_for_load(4);
  EXPECT_GE(adapted, 1);
  EXPECT_LE(adapted, 4);
  // OMP_NUM_THREADS set by the user: the count stands.
  const char* before = std::getenv("OMP_NUM_THREADS");
  const std::string saved = before ? before : "";
  setenv("OMP_NUM_THREADS", "3", 1);
  EXPECT_EQ(threads_for_load(64), 64);
  if (before) setenv("OMP_NUM_THREADS", saved.c_str(), 1);
  else unsetenv("OMP_NUM_THREADS");
}

}  // namespace ffeti

#include "hard_case_record.h"

#include <gtest/gtest.h>

#include <sstream>

namespace ffeti::test {

void record(const std::string& scene, const FetiResult& r, double error, const std::string& check,
            double kkt_bound) {
  if (kkt_bound > 0)
    EXPECT_LT(r.kkt.max(), kkt_bound) << scene << ": equilibrium " << r.kkt.equilibrium << ", equality " << r.kkt.equality
                                      << ", inequality " << r.kkt.inequality << ", complementarity " << r.kkt.complementarity
                                      << ", violation seen by the stop " << r.violation;
  std::ostringstream row;
  row.precision(3);
  row << "status=" << to_string(r.status) << ";path=" << path_name(r.path) << ";outer=" << r.counts.outer
      << ";hessian=" << r.counts.hessian << ";kkt=" << r.kkt.max() << ";error=" << error << ";check=" << check
      << ";active=" << r.active_contact << ";seconds=" << r.times.solve + r.times.norm_estimate;
  ::testing::Test::RecordProperty("row " + scene, row.str());
}

}  // namespace ffeti::test

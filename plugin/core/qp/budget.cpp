#include "qp/budget.h"

#include <stdexcept>

namespace ffeti::qp {

Budget::Budget(int max_hessian) : max_hessian_(max_hessian) {
  if (max_hessian < 1) throw std::invalid_argument("maxit: must be >= 1");
}

}  // namespace ffeti::qp

// The sparse matrix and vector types of every layer (Eigen's, with int indices as CHOLMOD's
// int interface wants them).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace ffeti {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Vec = Eigen::VectorXd;

}  // namespace ffeti

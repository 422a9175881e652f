// y = sum over all subdomains s of the contributions of s to its constraint rows, with
// subdomains spread over ranks. Every rank receives every contribution (one allgather)
// and adds them in global subdomain order: the result is bitwise the same on every rank
// and for any number of ranks and threads.
#pragma once

#include "parallel/communicator.h"

#include <Eigen/Core>

#include <vector>

namespace ffeti {

class SubdomainSum {
 public:
  /// rows[s]: the rows subdomain s touches (global numbering of subdomains and rows);
  /// owner[s]: the rank holding s. Each rank holds its subdomains in ascending order.
  SubdomainSum(std::vector<std::vector<int>> rows, const std::vector<int>& owner, int row_count,
               const Communicator& comm);

  /// `local` is this rank's contributions, subdomain after subdomain (ascending global
  /// index), rows[s].size() values each. y gets the m-vector of sums.
  void sum(const std::vector<double>& local, Eigen::VectorXd& y) const;

  const std::vector<int>& rows(int subdomain) const { return rows_[static_cast<size_t>(subdomain)]; }
  const Communicator& communicator() const { return comm_; }

 private:
  std::vector<std::vector<int>> rows_;
  std::vector<size_t> position_;  // start of subdomain s in the gathered buffer
  std::vector<int> rank_count_, rank_offset_;  // each rank's part of the gathered buffer
  int row_count_;
  const Communicator& comm_;
  mutable std::vector<double> gathered_;  // reused by every sum
};

}  // namespace ffeti

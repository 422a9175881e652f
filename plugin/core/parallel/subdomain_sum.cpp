#include "parallel/subdomain_sum.h"

namespace ffeti {

SubdomainSum::SubdomainSum(std::vector<std::vector<int>> rows, const std::vector<int>& owner,
                           int row_count, const Communicator& comm)
    : rows_(std::move(rows)), position_(rows_.size()), row_count_(row_count), comm_(comm) {
  // The gathered buffer holds rank 0's subdomains (ascending), then rank 1's, ...
  std::vector<size_t> rank_length(static_cast<size_t>(comm.size()), 0);
  for (size_t s = 0; s < rows_.size(); ++s) rank_length[static_cast<size_t>(owner[s])] += rows_[s].size();
  std::vector<size_t> next(static_cast<size_t>(comm.size()), 0);
  for (size_t r = 1; r < next.size(); ++r) next[r] = next[r - 1] + rank_length[r - 1];
  for (size_t r = 0; r < next.size(); ++r) {
    rank_offset_.push_back(static_cast<int>(next[r]));
    rank_count_.push_back(static_cast<int>(rank_length[r]));
  }
  for (size_t s = 0; s < rows_.size(); ++s) {
    position_[s] = next[static_cast<size_t>(owner[s])];
    next[static_cast<size_t>(owner[s])] += rows_[s].size();
  }
}

void SubdomainSum::sum(const std::vector<double>& local, Eigen::VectorXd& y) const {
  comm_.allgather_known(local, rank_count_, rank_offset_, gathered_);
  y.setZero(row_count_);
  for (size_t s = 0; s < rows_.size(); ++s)
    for (size_t k = 0; k < rows_[s].size(); ++k) y[rows_[s][k]] += gathered_[position_[s] + k];
}

}  // namespace ffeti

// Communicator over an MPI communicator (Open MPI). The caller keeps MPI initialized and
// the communicator valid for the lifetime of this object.
#pragma once

#include "parallel/communicator.h"

#include <mpi.h>

namespace ffeti {

class MpiCommunicator final : public Communicator {
 public:
  explicit MpiCommunicator(MPI_Comm comm);
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  std::vector<double> allgather(const std::vector<double>& local, std::vector<int>* counts) const override;
  std::vector<long long> allgather(const std::vector<long long>& local, std::vector<int>* counts) const override;
  void allgather_known(const std::vector<double>& local, const std::vector<int>& counts,
                       const std::vector<int>& offsets, std::vector<double>& out) const override;
  double sum(double local) const override;
  double max(double local) const override;
  std::string first_error(const std::string& local_error) const override;

 private:
  template <class T>
  std::vector<T> gather(const std::vector<T>& local, MPI_Datatype type, std::vector<int>* counts) const;
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

/// Default OpenMP threads per rank: the node's cores shared by the ranks on the node, so
/// that ranks and threads do not fight for the same cores; in one process or without MPI,
/// OpenMP's default less the cores other processes keep busy now (threads_for_load).
int default_threads_per_rank(const Communicator& comm);

}  // namespace ffeti

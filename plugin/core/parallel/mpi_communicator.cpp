#include "parallel/mpi_communicator.h"

#include "parallel/process.h"

#include <algorithm>

namespace ffeti {

MpiCommunicator::MpiCommunicator(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

template <class T>
std::vector<T> MpiCommunicator::gather(const std::vector<T>& local, MPI_Datatype type,
                                       std::vector<int>* counts) const {
  const int count = static_cast<int>(local.size());
  std::vector<int> all_counts(static_cast<size_t>(size_)), offsets(static_cast<size_t>(size_), 0);
  MPI_Allgather(&count, 1, MPI_INT, all_counts.data(), 1, MPI_INT, comm_);
  for (int r = 1; r < size_; ++r) offsets[static_cast<size_t>(r)] = offsets[static_cast<size_t>(r) - 1] + all_counts[static_cast<size_t>(r) - 1];
  std::vector<T> result(static_cast<size_t>(offsets.back() + all_counts.back()));
  MPI_Allgatherv(local.data(), count, type, result.data(), all_counts.data(), offsets.data(), type, comm_);
  if (counts) *counts = std::move(all_counts);
  return result;
}

std::vector<double> MpiCommunicator::allgather(const std::vector<double>& local, std::vector<int>* counts) const {
  return gather(local, MPI_DOUBLE, counts);
}

std::vector<long long> MpiCommunicator::allgather(const std::vector<long long>& local, std::vector<int>* counts) const {
  return gather(local, MPI_LONG_LONG, counts);
}

void MpiCommunicator::allgather_known(const std::vector<double>& local, const std::vector<int>& counts,
                                      const std::vector<int>& offsets, std::vector<double>& out) const {
  out.resize(static_cast<size_t>(offsets.back() + counts.back()));
  MPI_Allgatherv(local.data(), static_cast<int>(local.size()), MPI_DOUBLE, out.data(), counts.data(), offsets.data(),
                 MPI_DOUBLE, comm_);
}

double MpiCommunicator::sum(double local) const {
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return global;
}

double MpiCommunicator::max(double local) const {
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return global;
}

std::string MpiCommunicator::first_error(const std::string& local_error) const {
  const int candidate = local_error.empty() ? size_ : rank_;
  int failing = size_;
  MPI_Allreduce(&candidate, &failing, 1, MPI_INT, MPI_MIN, comm_);
  if (failing == size_) return "";
  int length = static_cast<int>(local_error.size());
  MPI_Bcast(&length, 1, MPI_INT, failing, comm_);
  std::string message = local_error;
  message.resize(static_cast<size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, failing, comm_);
  return size_ > 1 ? "rank " + std::to_string(failing) + ": " + message : message;
}

int default_threads_per_rank(const Communicator& comm) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized || comm.size() == 1) return threads_for_load(resolve_thread_count(0));
  MPI_Comm node;
  int node_ranks = 1;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &node_ranks);
  MPI_Comm_free(&node);
  return std::max(1, resolve_thread_count(0) / node_ranks);
}

}  // namespace ffeti

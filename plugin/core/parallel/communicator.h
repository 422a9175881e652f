// The few collective operations ffeti needs across processes, behind an interface so that
// the core runs unchanged in one process (SerialCommunicator) or over MPI ranks.
// Every operation is collective: all ranks of the communicator call it, in the same order.
#pragma once

#include "base/parallel_for.h"

#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ffeti {

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;

  /// Every rank's `local` concatenated in rank order; `counts` receives each rank's length.
  /// The same bytes arrive on every rank.
  virtual std::vector<double> allgather(const std::vector<double>& local, std::vector<int>* counts = nullptr) const = 0;
  virtual std::vector<long long> allgather(const std::vector<long long>& local, std::vector<int>* counts = nullptr) const = 0;

  /// The same with every rank's length known beforehand (`counts`, `offsets` in rank order)
  /// into `out`, resized to the total: no exchange of lengths, no allocation once `out` has
  /// its size (the dual operator's sums, once per application).
  virtual void allgather_known(const std::vector<double>& local, const std::vector<int>& counts,
                               const std::vector<int>& offsets, std::vector<double>& out) const = 0;

  virtual double sum(double local) const = 0;
  virtual double max(double local) const = 0;

  /// The message of the lowest rank whose `local_error` is not empty ("" if none): lets all
  /// ranks fail together instead of leaving the others waiting in a collective.
  virtual std::string first_error(const std::string& local_error) const = 0;
};

class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<double> allgather(const std::vector<double>& local, std::vector<int>* counts) const override;
  std::vector<long long> allgather(const std::vector<long long>& local, std::vector<int>* counts) const override;
  void allgather_known(const std::vector<double>& local, const std::vector<int>&, const std::vector<int>&,
                       std::vector<double>& out) const override {
    out.assign(local.begin(), local.end());
  }
  double sum(double local) const override { return local; }
  double max(double local) const override { return local; }
  std::string first_error(const std::string& local_error) const override { return local_error; }
};

/// Runs `step` on every rank; if it throws on any rank, every rank throws the lowest failing
/// rank's failure: on one rank the exception itself; on several an InputError where that was
/// bad input, else a std::runtime_error (memory, a library), with its message prefixed by
/// that rank.
void collectively(const Communicator& comm, const std::function<void()>& step);

/// If `failure` is set on any rank, every rank throws: on one rank the failure itself, on
/// several the lowest failing rank's failure (collectively). Costs one
/// reduction on several ranks.
void rethrow_on_every_rank(const Communicator& comm, const std::exception_ptr& failure);

/// parallel_for_each on this rank's items, then rethrow_on_every_rank: for a threaded loop
/// that a collective step follows (a subdomain solve out of memory on one rank must not
/// leave the others waiting in that step, nor end the process from inside a thread).
template <class Body>
void parallel_for_each_on_every_rank(const Communicator& comm, int count, int threads, Body&& body) {
  std::exception_ptr failure;
  try {
    parallel_for_each(count, threads, std::forward<Body>(body));
  } catch (...) {
    failure = std::current_exception();
  }
  rethrow_on_every_rank(comm, failure);
}

}  // namespace ffeti

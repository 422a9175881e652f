#include "parallel/communicator.h"

#include "base/errors.h"

namespace ffeti {

std::vector<double> SerialCommunicator::allgather(const std::vector<double>& local, std::vector<int>* counts) const {
  if (counts) *counts = {static_cast<int>(local.size())};
  return local;
}

std::vector<long long> SerialCommunicator::allgather(const std::vector<long long>& local,
                                                     std::vector<int>* counts) const {
  if (counts) *counts = {static_cast<int>(local.size())};
  return local;
}

void collectively(const Communicator& comm, const std::function<void()>& step) {
  std::string error;
  try {
    step();
  } catch (const std::exception& e) {
    error = e.what();
    if (error.empty()) error = "unknown error";
  }
  const std::string first = comm.first_error(error);
  if (!first.empty()) throw InputError(first);
}

void rethrow_on_every_rank(const Communicator& comm, const std::exception_ptr& failure) {
  if (comm.size() == 1) {
    if (failure) std::rethrow_exception(failure);
    return;
  }
  if (comm.max(failure ? 1.0 : 0.0) > 0) collectively(comm, [&] {
      if (failure) std::rethrow_exception(failure);
    });
}

}  // namespace ffeti

#include "parallel/communicator.h"

#include "base/errors.h"

#include <exception>
#include <stdexcept>
#include <string>

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
  // The kind of the failure travels with its message, one letter ahead of it: 'I' bad input,
  // 'F' another failure (memory, a library), so that every rank throws the same kind.
  std::exception_ptr failure;
  std::string error;
  try {
    step();
  } catch (const InputError& e) {
    failure = std::current_exception();
    error = std::string("I") + e.what();
  } catch (const std::exception& e) {
    failure = std::current_exception();
    error = std::string("F") + (*e.what() ? e.what() : "unknown error");
  }
  if (comm.size() == 1) {
    if (failure) std::rethrow_exception(failure);
    return;
  }
  std::string first = comm.first_error(error);  // "rank r: " + kind + message
  if (first.empty()) return;
  const size_t kind_at = first.find(": ") + 2;
  const char kind = first[kind_at];
  first.erase(kind_at, 1);
  if (kind == 'I') throw InputError(first);
  throw std::runtime_error(first);
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

#include "feti/held_bytes.h"

#include <unordered_set>

namespace ffeti {

double input_bytes(const std::vector<SubdomainInput>& inputs) {
  double bytes = 0;
  std::unordered_set<const SparseMatrix*> counted;
  for (const SubdomainInput& in : inputs) {
    if (counted.insert(&in.K.get()).second) bytes += sparse_bytes(in.K.get());
    bytes += static_cast<double>(in.f.size()) * sizeof(double);
    bytes += vector_bytes(in.x) + vector_bytes(in.y) + vector_bytes(in.z) + vector_bytes(in.component);
    bytes += vector_bytes(in.dirichlet_dofs) + vector_bytes(in.dirichlet_values);
  }
  return bytes;
}

double kernel_bytes(const SubdomainList& subdomains) {
  double bytes = 0;
  for (const auto& s : subdomains)
    bytes += static_cast<double>(s->kernel().size()) * sizeof(double) + vector_bytes(s->fixing()) +
             vector_bytes(s->interface());
  return bytes;
}

double explicit_block_bytes(const SubdomainList& subdomains) {
  double bytes = 0;
  std::unordered_set<const PackedSymmetric*> counted;
  for (const auto& s : subdomains)
    if (s->explicit_block() && counted.insert(s->explicit_block()).second) bytes += s->explicit_block()->bytes();
  return bytes;
}

double constraint_bytes(const Constraints& constraints) {
  return vector_bytes(constraints.row_start) + vector_bytes(constraints.entries) + vector_bytes(constraints.rhs) +
         vector_bytes(constraints.kind);
}

}  // namespace ffeti

#include "mesh/connect_parts.h"

#include "base/errors.h"
#include "mesh/facet_neighbours.h"

#include <algorithm>
#include <map>
#include <string>

namespace ffeti {
namespace {

/// Facet-connected pieces of the parts: piece[k] for each element, the size of each piece.
struct Pieces {
  std::vector<int> piece, size;
};

Pieces find_pieces(const std::vector<std::vector<int>>& neighbours, const std::vector<long>& part) {
  const int nt = static_cast<int>(part.size());
  Pieces p;
  p.piece.assign(part.size(), -1);
  std::vector<int> stack;
  for (int start = 0; start < nt; ++start) {
    if (p.piece[static_cast<size_t>(start)] >= 0) continue;
    const int id = static_cast<int>(p.size.size());
    p.size.push_back(0);
    stack.assign(1, start);
    p.piece[static_cast<size_t>(start)] = id;
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      ++p.size[static_cast<size_t>(id)];
      for (int other : neighbours[static_cast<size_t>(k)])
        if (other >= 0 && other != k && p.piece[static_cast<size_t>(other)] < 0 &&
            part[static_cast<size_t>(other)] == part[static_cast<size_t>(k)]) {
          p.piece[static_cast<size_t>(other)] = id;
          stack.push_back(other);
        }
    }
  }
  return p;
}

}  // namespace

long connect_parts(const std::vector<std::vector<int>>& neighbours, std::vector<long>& part) {
  if (part.size() != neighbours.size())
    throw InputError("part: has " + std::to_string(part.size()) + " entries for " + std::to_string(neighbours.size()) +
                     " elements");
  const size_t nt = part.size();
  // Each part's main piece is the one holding its anchor, an element of its largest piece at
  // the start. Main pieces never move, and stray pieces join main pieces only: moving
  // strays into strays let two of them swap parts round after round (a partition dealt at
  // random never settled), while this way every round shrinks the stray elements.
  std::map<long, size_t> anchor;
  {
    const Pieces p = find_pieces(neighbours, part);
    for (size_t k = 0; k < nt; ++k) {
      auto [it, inserted] = anchor.emplace(part[k], k);
      if (!inserted && p.size[static_cast<size_t>(p.piece[k])] > p.size[static_cast<size_t>(p.piece[it->second])])
        it->second = k;
    }
  }
  long moved = 0;
  for (;;) {
    const Pieces p = find_pieces(neighbours, part);
    std::vector<bool> main(p.size.size(), false);
    for (const auto& [owner, k] : anchor) main[static_cast<size_t>(p.piece[k])] = true;
    std::map<int, std::map<long, int>> shared;  // stray piece -> part of a main piece next to it -> shared facets
    for (size_t k = 0; k < nt; ++k) {
      const int id = p.piece[k];
      if (main[static_cast<size_t>(id)]) continue;
      for (int other : neighbours[k]) {
        if (other < 0 || static_cast<size_t>(other) == k) continue;
        if (main[static_cast<size_t>(p.piece[static_cast<size_t>(other)])]) ++shared[id][part[static_cast<size_t>(other)]];
      }
    }
    // None: every part is connected, or the strays left lie in a piece of the mesh that
    // holds no main piece (a mesh in several pieces), where nothing can join anything.
    if (shared.empty()) break;
    std::map<int, long> target;
    for (const auto& [id, counts] : shared)
      target[id] = std::max_element(counts.begin(), counts.end(),
                                    [](const auto& a, const auto& b) { return a.second < b.second; })->first;
    for (size_t k = 0; k < nt; ++k)
      if (const auto it = target.find(p.piece[k]); it != target.end()) {
        part[k] = it->second;
        ++moved;
      }
  }
  return moved;
}

long connect_element_parts(const std::vector<int>& element_nodes, int nodes_per_element, std::vector<long>& part) {
  return connect_parts(facet_neighbours(element_nodes, nodes_per_element), part);
}

}  // namespace ffeti

#include "mesh/connect_parts.h"

#include "base/errors.h"

#include <algorithm>
#include <map>
#include <string>

namespace ffeti {
namespace {

/// Edge-connected pieces of the parts: piece[k] for each triangle, the size of each piece.
struct Pieces {
  std::vector<int> piece, size;
};

Pieces find_pieces(const std::vector<std::array<int, 3>>& neighbours, const std::vector<long>& part) {
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

long connect_parts(const std::vector<std::array<int, 3>>& neighbours, std::vector<long>& part) {
  if (part.size() != neighbours.size())
    throw InputError("part: has " + std::to_string(part.size()) + " entries for " + std::to_string(neighbours.size()) +
                     " triangles");
  const size_t nt = part.size();
  long moved = 0;
  for (int round = 0; round < 100; ++round) {
    const Pieces p = find_pieces(neighbours, part);
    std::map<long, int> largest;  // part -> its largest piece
    for (size_t k = 0; k < nt; ++k) {
      const int id = p.piece[k];
      auto [it, inserted] = largest.emplace(part[k], id);
      if (!inserted && p.size[static_cast<size_t>(id)] > p.size[static_cast<size_t>(it->second)]) it->second = id;
    }
    std::map<int, std::map<long, int>> shared;  // stray piece -> neighbouring part -> shared edges
    for (size_t k = 0; k < nt; ++k) {
      const int id = p.piece[k];
      if (largest[part[k]] == id) continue;
      for (int other : neighbours[k])
        if (other >= 0 && static_cast<size_t>(other) != k && part[static_cast<size_t>(other)] != part[k])
          ++shared[id][part[static_cast<size_t>(other)]];
    }
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

}  // namespace ffeti

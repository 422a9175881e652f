// A stable sort on the set-up's threads: the interface records of thousands of subdomains
// (9 million at 8192 boxes) sorted on one core took most of the constraints' set-up.
#pragma once

#include "base/parallel_for.h"

#include <algorithm>
#include <vector>

namespace ffeti {

/// Sorts v stably by `less`, the same order as std::stable_sort: contiguous parts sorted
/// stably on the available threads, then merged pairwise (std::inplace_merge keeps the
/// left part's elements first among equals). Small vectors sort on one thread.
template <class T, class Less>
void parallel_stable_sort(std::vector<T>& v, Less less) {
  constexpr size_t kPartMinimum = 1 << 16;  // below this a part's thread costs more than it saves
  const size_t parts = std::max<size_t>(1, std::min<size_t>(static_cast<size_t>(available_threads()), v.size() / kPartMinimum));
  if (parts == 1) {
    std::stable_sort(v.begin(), v.end(), less);
    return;
  }
  std::vector<size_t> bounds(parts + 1);
  for (size_t k = 0; k <= parts; ++k) bounds[k] = v.size() * k / parts;
  parallel_for_each(static_cast<int>(parts), static_cast<int>(parts), [&](int k) {
    std::stable_sort(v.begin() + static_cast<long>(bounds[static_cast<size_t>(k)]),
                     v.begin() + static_cast<long>(bounds[static_cast<size_t>(k) + 1]), less);
  });
  for (size_t width = 1; width < parts; width *= 2) {  // merge neighbouring runs, doubling
    const auto merges = static_cast<int>((parts + 2 * width - 1) / (2 * width));
    parallel_for_each(merges, merges, [&](int m) {
      const size_t first = 2 * width * static_cast<size_t>(m), middle = std::min(first + width, parts),
                   last = std::min(first + 2 * width, parts);
      if (middle < last)
        std::inplace_merge(v.begin() + static_cast<long>(bounds[first]), v.begin() + static_cast<long>(bounds[middle]),
                           v.begin() + static_cast<long>(bounds[last]), less);
    });
  }
}

}  // namespace ffeti

#include "kuhn_box.h"

#include <array>
#include <cstddef>

namespace ffeti {

std::vector<int> kuhn_box(int n) {
  const auto node = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  const std::array<std::array<int, 3>, 6> orders = {{{0, 1, 2}, {1, 0, 2}, {1, 2, 0}, {2, 1, 0}, {2, 0, 1}, {0, 2, 1}}};
  std::vector<int> nodes;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& order : orders) {
          std::array<int, 3> at{i, j, k};
          nodes.push_back(node(at[0], at[1], at[2]));
          for (int axis : order) {
            ++at[static_cast<size_t>(axis)];
            nodes.push_back(node(at[0], at[1], at[2]));
          }
        }
  return nodes;
}

}  // namespace ffeti

// Mesh partitions whose parts are connected: a disconnected subdomain has rigid modes that
// no kernel candidate covers, and METIS may give a part two pieces (both jaws of a spanner).
#pragma once

#include <array>
#include <vector>

namespace ffeti {

/// Makes every part of a partition of a triangle mesh connected through element edges:
/// each edge-connected piece of a part other than its largest goes to the neighbouring part
/// it shares most edges with, until no piece is left (at most 100 rounds). `neighbours[k]`
/// are the triangles across the three edges of triangle k (-1 on the boundary, or k
/// itself); `part[k]` is triangle k's part, changed in place. Returns the number of
/// triangles moved. InputError when the sizes differ.
long connect_parts(const std::vector<std::array<int, 3>>& neighbours, std::vector<long>& part);

}  // namespace ffeti

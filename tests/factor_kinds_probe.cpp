// Times CHOLMOD's simplicial, supernodal and automatic factors of one subdomain-like matrix
// (a P1 pattern on a structured 2D or 3D grid, scalar or with 2/3 components per node) and
// prints one CSV line per kind: the measurements behind the automatic choice's switch
// (driven by scripts/factor_kinds.py under each BLAS and thread count).
//   factor_kinds_probe DIM COMPONENTS CELLS [THREADS] [REPEAT]
#include "factor/blas_library.h"
#include "factor/cholmod_factor.h"
#include "base/stopwatch.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

using namespace ffeti;

namespace {

/// SPD matrix with the pattern of P1 elements on a grid of cells^dim cells (each square
/// cut into two triangles, each cube into Kuhn's six tetrahedra: the nodes joined by an
/// edge differ by e_i, e_i + e_j or e_1 + e_2 + e_3) with `components` dofs per node:
/// a shifted graph Laplacian times an SPD block (the values do not change the work).
SparseMatrix grid_matrix(int dim, int components, int cells) {
  const int m = cells + 1, nodes = dim == 2 ? m * m : m * m * m;
  std::vector<std::array<int, 3>> offsets;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < (dim == 3 ? 2 : 1); ++c)
        if (a + b + c > 0) offsets.push_back({a, b, c});  // Kuhn's edges join nodes u <= v
  std::vector<Eigen::Triplet<double, int>> entries;
  const auto id = [m](int x, int y, int z) { return (z * m + y) * m + x; };
  std::vector<int> degree(static_cast<size_t>(nodes), 0);
  const auto couple = [&](int i, int j) {
    for (int c = 0; c < components; ++c)
      for (int d = 0; d < components; ++d) {
        const double block = c == d ? -1.0 : -0.3;
        entries.emplace_back(components * i + c, components * j + d, block);
        entries.emplace_back(components * j + d, components * i + c, block);
      }
    ++degree[static_cast<size_t>(i)], ++degree[static_cast<size_t>(j)];
  };
  for (int z = 0; z < (dim == 3 ? m : 1); ++z)
    for (int y = 0; y < m; ++y)
      for (int x = 0; x < m; ++x)
        for (const auto& o : offsets)
          if (x + o[0] < m && y + o[1] < m && z + o[2] < m) couple(id(x, y, z), id(x + o[0], y + o[1], z + o[2]));
  for (int i = 0; i < nodes; ++i)
    for (int c = 0; c < components; ++c)
      for (int d = 0; d < components; ++d)
        entries.emplace_back(components * i + c, components * i + d, (degree[static_cast<size_t>(i)] + 0.01) * (c == d ? 1.0 : 0.3));
  SparseMatrix A(components * nodes, components * nodes);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s DIM COMPONENTS CELLS [THREADS] [REPEAT]\n", argv[0]);
    return 2;
  }
  const int dim = std::atoi(argv[1]), components = std::atoi(argv[2]), cells = std::atoi(argv[3]);
  const int threads = argc > 4 ? std::atoi(argv[4]) : 1, repeat = argc > 5 ? std::atoi(argv[5]) : 3;
  const SparseMatrix A = grid_matrix(dim, components, cells);
  const Vec b = Vec::Ones(A.rows());
  const Eigen::MatrixXd block = Eigen::MatrixXd::Ones(A.rows(), 6);
  const char* names[] = {"simplicial", "supernodal", "automatic"};
  std::printf("dim,components,cells,dofs,nnz_A,flops,nnz_L,flops_per_nnz_L,kind,supernodal,analyze_s,factor_s,"
              "solve_s,solve6_s,blas,threads,concurrent_round_s,concurrent_difference,factor_bytes\n");
  for (FactorKind kind : {FactorKind::simplicial, FactorKind::supernodal, FactorKind::automatic}) {
    // One thread, as inside the plugin's loop over subdomains (an OpenMP OpenBLAS runs on
    // one thread there); the best of `repeat` runs, the machine being shared.
    omp_set_num_threads(1);
    double first = 1e300, numeric = 1e300, solve = 1e300, solve6 = 1e300;
    std::unique_ptr<CholmodFactor> factor;
    Vec reference;
    Eigen::MatrixXd X;
    for (int r = 0; r < repeat; ++r) {
      factor = std::make_unique<CholmodFactor>(kind);
      Stopwatch analyze_and_factor;
      if (factor->factorize(A) >= 0) return 1;
      first = std::min(first, analyze_and_factor.seconds());
      Stopwatch clock;
      factor->factorize(A);  // the same pattern: numeric only
      numeric = std::min(numeric, clock.seconds());
      Stopwatch s1;
      factor->solve(b, reference);
      solve = std::min(solve, s1.seconds());
      Stopwatch s6;
      factor->solve(block, X);
      solve6 = std::min(solve6, s6.seconds());
    }
    // `threads` factors at once, each its own: the wall time per round under the plugin's
    // loop over subdomains, and whether concurrent BLAS calls still give the same solve.
    std::vector<std::unique_ptr<CholmodFactor>> copies;
    for (int t = 0; t < threads; ++t) {
      copies.push_back(std::make_unique<CholmodFactor>(kind));
      copies.back()->factorize(A);
    }
    double difference = 0;
    omp_set_num_threads(threads);
    Stopwatch together;
#pragma omp parallel for num_threads(threads) schedule(static, 1) reduction(max : difference)
    for (int k = 0; k < threads * repeat; ++k) {
      CholmodFactor& f = *copies[static_cast<size_t>(k % threads)];
      Vec y;
      if (f.factorize(A) >= 0) difference = 1e300;
      f.solve(b, y);
      difference = std::max(difference, (y - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff());
    }
    const double concurrent = together.seconds() / repeat;
    std::printf("%d,%d,%d,%ld,%ld,%.6g,%.6g,%.1f,%s,%d,%.6f,%.6f,%.6f,%.6f,%s,%d,%.6f,%.2g,%.17g\n", dim, components, cells,
                static_cast<long>(A.rows()), static_cast<long>(A.nonZeros()), factor->analysis_flops(),
                factor->analysis_nonzeros(), factor->analysis_flops() / factor->analysis_nonzeros(), names[int(kind)],
                factor->supernodal() ? 1 : 0, first - numeric, numeric, solve, solve6, blas_name(loaded_blas()),
                threads, concurrent, difference, factor->factor_bytes());
  }
  return 0;
}

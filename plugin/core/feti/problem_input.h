// What a front end (the FreeFEM binding, a test) hands to the core for one problem.
#pragma once

#include "feti/cholmod_factor.h"

#include <vector>

namespace ffeti {

/// One subdomain's finite element data. Dofs that stand for the same physical node and
/// field component in several subdomains of one body are recognised by equal coordinates
/// and glued; dofs of different bodies are never glued.
struct SubdomainInput {
  SparseMatrix K;                 ///< stiffness, symmetric, full (not half) storage
  Vec f;                          ///< load
  std::vector<double> x, y;       ///< coordinates of each dof's node
  std::vector<int> component;     ///< field component of each dof (empty: scalar field)
  int body = 0;                   ///< body the subdomain belongs to
  std::vector<int> dirichlet_dofs;      ///< local dofs with a prescribed value
  std::vector<double> dirichlet_values; ///< their values (empty: all zero)
};

/// Node-to-node contact on matching meshes: each slave dof s pairs with the master dof m
/// of another body at the same position and component, giving the row u_s - u_m <= gap.
/// (For the seed's membranes, u1(1,y) <= u2(1,y): slaves on body 1, masters on body 2.)
struct NodeToNodeContact {
  std::vector<std::vector<int>> slave_dofs;   ///< per subdomain (may be empty)
  std::vector<std::vector<int>> master_dofs;  ///< per subdomain (may be empty)
  double gap = 0;
};

enum class FetiVariant {
  feti1,  ///< Dirichlet dofs eliminated inside K_s (the seed); touching subdomains are regular
  tfeti,  ///< Total FETI: Dirichlet conditions are rows of B_E; every subdomain floats
};

}  // namespace ffeti

// The contact discretizations build_constraints runs, in the order of their rows in B (that
// order is part of the numerics: keep it when adding a kind, append the new one).
#include "constraints/contact/ball.h"
#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/mortar.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/node_to_node.h"
#include "constraints/contact/node_to_segment.h"
#include "constraints/contact/obstacle.h"

namespace ffeti {

const std::vector<std::unique_ptr<const ContactDiscretization>>& contact_discretizations() {
  static const auto units = [] {
    std::vector<std::unique_ptr<const ContactDiscretization>> list;
    list.push_back(std::make_unique<NodeToSegment>());
    list.push_back(std::make_unique<Obstacle>());
    list.push_back(std::make_unique<Ball>());
    list.push_back(std::make_unique<Mortar>());
    list.push_back(std::make_unique<NodeToFace>());
    list.push_back(std::make_unique<NodeToNode>());
    return list;
  }();
  return units;
}

}  // namespace ffeti

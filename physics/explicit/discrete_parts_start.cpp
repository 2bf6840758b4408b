// DiscreteParts::start_from_preload: the bodies' positions at the start of a run that follows
// a statics step (which knows nothing of them).
#include "physics/explicit/discrete_parts.hpp"

namespace railfe {

void DiscreteParts::start_from_preload(const NodalArrays& nodes,
                                       const std::array<double, 3>& gravity,
                                       const Communicator& comm) {
  const std::size_t n = bodies_.size();
  if (n == 0)
    return;
  // Bodies that carry nodes follow them: the mean of their displacements.
  std::vector<double> sums(4 * n, 0.0);
  for (std::size_t b = 0; b < n; ++b) {
    for (LocalIndex node : bodies_[b].nodes) {
      for (int d = 0; d < 3; ++d)
        sums[4 * b + d] += nodes.u[3 * node + d];
    }
    sums[4 * b + 3] = static_cast<double>(bodies_[b].nodes.size());
  }
  // Each spring from a node set pulls its body towards the set's mean displacement.
  std::vector<double> set_means(3 * springs_.size(), 0.0);
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    for (LocalIndex node : springs_[s].a.nodes) {
      for (int d = 0; d < 3; ++d)
        set_means[3 * s + d] += springs_[s].a.share * nodes.u[3 * node + d];
    }
  }
  sums.insert(sums.end(), set_means.begin(), set_means.end());
  comm.sum_in_place(sums);
  std::vector<bool> known(n, false);
  for (std::size_t b = 0; b < n; ++b) {
    if (sums[4 * b + 3] > 0) {
      known[b] = true;
      for (int d = 0; d < 3; ++d)
        bodies_[b].displacement[d] = bodies_[b].fixed[d] ? 0 : sums[4 * b + d] / sums[4 * b + 3];
    }
  }
  // The point bodies: per direction, K U = F over the bodies not yet placed.
  for (int d = 0; d < 3; ++d) {
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd F = Eigen::VectorXd::Zero(n);
    auto free = [&](int b) {
      return b >= 0 && !known[b] && !bodies_[b].fixed[d] && bodies_[b].motion[d] < 0;
    };
    auto position = [&](int b) { return b >= 0 && !free(b) ? bodies_[b].displacement[d] : 0.0; };
    for (std::size_t s = 0; s < springs_.size(); ++s) {
      const Spring& spring = springs_[s];
      // The whole spring's stiffness (a node-set end's element holds one node's share).
      const double k = spring.element.stiffness[d] / (spring.a.share > 0 ? spring.a.share : 1.0);
      const int a = spring.a.body, b = spring.b.body;
      if (spring.a.share > 0) {
        // A node set (share > 0 on every rank, even one that owns none of its nodes).
        if (free(b)) {
          K(b, b) += k;
          F(b) += k * sums[4 * n + 3 * s + d];
        }
        continue;
      }
      if (free(a)) {
        K(a, a) += k;
        F(a) += k * position(b);
      }
      if (free(b)) {
        K(b, b) += k;
        F(b) += k * position(a);
      }
      if (free(a) && free(b)) {
        K(a, b) -= k;
        K(b, a) -= k;
      }
    }
    for (std::size_t b = 0; b < n; ++b) {
      if (free(static_cast<int>(b)) && bodies_[b].weighs)
        F(b) += bodies_[b].mass * gravity[d];
    }
    // A free body without a spring in this direction stays where it is (it would drift).
    for (std::size_t b = 0; b < n; ++b) {
      if (!free(static_cast<int>(b)) || K(b, b) <= 0) {
        K.row(b).setZero();
        K.col(b).setZero();
        K(b, b) = 1;
        F(b) = free(static_cast<int>(b)) ? 0 : bodies_[b].displacement[d];
      }
    }
    const Eigen::VectorXd U = K.ldlt().solve(F);
    for (std::size_t b = 0; b < n; ++b) {
      if (free(static_cast<int>(b)))
        bodies_[b].displacement[d] = U(b);
    }
  }
  for (auto& body : bodies_)
    body.motion_origin = body.displacement;  // a prescribed motion starts from here
}

}  // namespace railfe

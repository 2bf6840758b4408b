#include "physics/explicit/lanczos.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace railfe {

namespace {

double dot(const double* a, const double* b, std::size_t n, const Communicator& comm) {
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i)
    sum += a[i] * b[i];
  return comm.sum(sum);
}

// A reproducible pseudo-random value in [−1, 1] for a global index (splitmix64).
double hashed(GlobalIndex seed) {
  unsigned long long z = static_cast<unsigned long long>(seed) + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / static_cast<double>(1ULL << 52) - 1.0;
}

}  // namespace

double largest_eigenvalue(const std::function<void(const double*, double*)>& add_product,
                          std::size_t n,
                          const std::function<GlobalIndex(std::size_t)>& global_index, double* q,
                          double* p, const Communicator& comm, double tolerance,
                          int max_iterations) {
  for (std::size_t i = 0; i < n; ++i)
    q[i] = hashed(global_index(i));
  const double norm = std::sqrt(dot(q, q, n, comm));
  if (norm == 0)
    return 0;
  for (std::size_t i = 0; i < n; ++i) {
    q[i] /= norm;
    p[i] = 0;
  }
  // Paige's two-vector recurrence: p enters holding −β_{k−1} q_{k−1} and leaves as β_k q_{k+1}.
  std::vector<double> alpha, beta;
  double largest = 0;
  for (int k = 0; k < max_iterations; ++k) {
    add_product(q, p);
    const double a = dot(q, p, n, comm);
    alpha.push_back(a);
    for (std::size_t i = 0; i < n; ++i)
      p[i] -= a * q[i];
    const double b = std::sqrt(dot(p, p, n, comm));
    // The largest eigenvalue of the tridiagonal Lanczos matrix so far.
    const int m = static_cast<int>(alpha.size());
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(m, m);
    for (int i = 0; i < m; ++i) {
      T(i, i) = alpha[i];
      if (i + 1 < m)
        T(i, i + 1) = T(i + 1, i) = beta[i];
    }
    const double estimate =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(T, Eigen::EigenvaluesOnly)
            .eigenvalues()
            .maxCoeff();
    const bool converged = k >= 5 && std::abs(estimate - largest) <= tolerance * estimate;
    largest = estimate;
    if (converged || b <= 1e-14 * std::abs(estimate))
      break;
    beta.push_back(b);
    for (std::size_t i = 0; i < n; ++i) {
      const double current = q[i];
      q[i] = p[i] / b;
      p[i] = -b * current;
    }
  }
  return largest;
}

}  // namespace railfe

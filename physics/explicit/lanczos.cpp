#include "physics/explicit/lanczos.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace railfe {

namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b, const Communicator& comm) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
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

double largest_eigenvalue(const std::function<void(const double*, double*)>& apply,
                          const std::vector<GlobalIndex>& seeds, const Communicator& comm,
                          double tolerance, int max_iterations) {
  const std::size_t n = seeds.size();
  std::vector<double> q(n), previous(n, 0.0), w(n);
  for (std::size_t i = 0; i < n; ++i)
    q[i] = hashed(seeds[i]);
  double norm = std::sqrt(dot(q, q, comm));
  if (norm == 0)
    return 0;
  for (double& value : q)
    value /= norm;
  std::vector<double> alpha, beta;
  double largest = 0;
  for (int k = 0; k < max_iterations; ++k) {
    apply(q.data(), w.data());
    const double a = dot(q, w, comm);
    alpha.push_back(a);
    const double b_previous = beta.empty() ? 0.0 : beta.back();
    for (std::size_t i = 0; i < n; ++i)
      w[i] -= a * q[i] + b_previous * previous[i];
    const double b = std::sqrt(dot(w, w, comm));
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
    previous.swap(q);
    for (std::size_t i = 0; i < n; ++i)
      q[i] = w[i] / b;
  }
  return largest;
}

}  // namespace railfe

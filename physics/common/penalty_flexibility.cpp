#include "physics/common/penalty_flexibility.hpp"

#include <cmath>
#include <stdexcept>

#include "contact/enforcement/penalty_contact_pair.hpp"
#include "contact/laws/kalker_linear.hpp"
#include "physics/common/contact_tables.hpp"

namespace railfe {

namespace {

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

PenaltyFlexibility penalty_flexibility(const PenaltyContactPair& pair, double shear_modulus,
                                       double poisson) {
  PenaltyFlexibility result;
  const PenaltyPairTotals& totals = pair.totals();
  result.normal_force = totals.normal_force;
  if (totals.active < 4 || totals.slipping >= totals.active || !(totals.normal_force > 0))
    return result;
  const auto frame = contact_frame(pair);
  const auto& geometry = pair.geometry();
  std::array<double, 3> centre{};
  for (const SlaveContact& slave : pair.slaves())
    if (slave.face >= 0)
      for (int d = 0; d < 3; ++d)
        centre[d] += slave.normal_force * slave.point[d] / totals.normal_force;
  double s1_squared = 0, s2_squared = 0, s1_area = 0, area = 0;
  for (std::size_t s = 0; s < pair.slaves().size(); ++s) {
    const SlaveContact& slave = pair.slaves()[s];
    if (slave.face < 0)
      continue;
    const double weight = slave.normal_force / totals.normal_force;
    std::array<double, 3> offset;
    for (int d = 0; d < 3; ++d)
      offset[d] = slave.point[d] - centre[d];
    s1_squared += weight * std::pow(dot(offset, frame[1]), 2);
    s2_squared += weight * std::pow(dot(offset, frame[2]), 2);
    s1_area += geometry.slave_area[s] * std::pow(dot(offset, frame[1]), 2);
    area += geometry.slave_area[s];
    result.penalty += weight * geometry.slave_area[s] / pair.stiffness(s, slave.face);
  }
  // A Hertz pressure over an ellipse has <s1²> = a²/5, the ellipse's area a²/4. A pressure
  // that does not peak inside along the rolling direction (a flat block, a punch) is not the
  // patch Kalker's flexibility is for.
  result.rolling_semi_axis = std::sqrt(5 * s1_squared);
  result.lateral_semi_axis = std::sqrt(5 * s2_squared);
  if (!(s1_squared < kPeakedPatch * s1_area / area))
    return result;
  try {
    const KalkerCoefficients c =
        KalkerTable::shipped().at(result.rolling_semi_axis, result.lateral_semi_axis, poisson);
    result.patch = 8 * result.rolling_semi_axis / (3 * c.C11 * shear_modulus);
  } catch (const std::invalid_argument&) {
    result.patch = 0;  // a line contact or a sliver: no ellipse to compare with
  }
  return result;
}

}  // namespace railfe

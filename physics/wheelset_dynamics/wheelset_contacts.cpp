#include "physics/wheelset_dynamics/wheelset_contacts.hpp"

#include <algorithm>

namespace railfe {

namespace {

constexpr TrackSide kSides[n_wheelset_contacts] = {TrackSide::right, TrackSide::right,
                                                   TrackSide::left, TrackSide::left};
constexpr bool kFlange[n_wheelset_contacts] = {false, true, false, true};

}  // namespace

const char* const wheelset_contact_names[n_wheelset_contacts] = {"right_tread", "right_flange",
                                                                 "left_tread", "left_flange"};

std::array<double, 2> wheel_forces(const std::array<ContactState, n_wheelset_contacts>& states,
                                   int side) {
  const int first = 2 * side;
  const double inward = side == 0 ? -1.0 : 1.0;  // the right wheel's centre side is −y
  double Q = 0, Y = 0;
  for (int k = first; k < first + 2; ++k) {
    Q -= states[k].force[2];
    Y += inward * states[k].force[1];
  }
  return {Q, Y};
}

WheelsetContacts::WheelsetContacts(std::shared_ptr<const WheelRailGeometry> geometry,
                                   const WheelRailContactSettings& settings,
                                   WheelsetUnknowns unknowns, double speed, double spin)
    : unknowns_(unknowns), speed_(speed), spin_(spin) {
  for (int k = 0; k < n_wheelset_contacts; ++k)
    contacts_.emplace_back(geometry, kSides[k], kFlange[k], settings);
}

void WheelsetContacts::set_spin(double spin) {
  spin_ = spin;
  cached_ = false;
}

void WheelsetContacts::set_rolling(bool rolling) {
  rolling_ = rolling;
  cached_ = false;
}

ContactKinematics WheelsetContacts::kinematics(int index, const double* u, const double* v) const {
  ContactKinematics state;
  std::copy_n(u + unknowns_.wheelset, 6, state.wheelset_u.begin());
  std::copy_n(v + unknowns_.wheelset, 6, state.wheelset_v.begin());
  std::copy_n(u + unknowns_.nodes + 3 * index, 3, state.node_u.begin());
  std::copy_n(v + unknowns_.nodes + 3 * index, 3, state.node_v.begin());
  state.speed = rolling_ ? speed_ : 0.0;
  state.spin = rolling_ ? spin_ : 0.0;
  return state;
}

bool WheelsetContacts::same_iterate(const double* u, const double* v) const {
  const double* c = iterate_.data();
  return cached_ && std::equal(u + unknowns_.wheelset, u + unknowns_.wheelset + 6, c) &&
         std::equal(v + unknowns_.wheelset, v + unknowns_.wheelset + 6, c + 6) &&
         std::equal(u + unknowns_.nodes, u + unknowns_.nodes + 12, c + 12) &&
         std::equal(v + unknowns_.nodes, v + unknowns_.nodes + 12, c + 24);
}

const std::array<ContactState, n_wheelset_contacts>& WheelsetContacts::states(const double* u,
                                                                              const double* v) {
  if (!same_iterate(u, v)) {
    for (int k = 0; k < n_wheelset_contacts; ++k)
      states_[k] = contacts_[k].evaluate(kinematics(k, u, v));
    double* c = iterate_.data();
    std::copy_n(u + unknowns_.wheelset, 6, c);
    std::copy_n(v + unknowns_.wheelset, 6, c + 6);
    std::copy_n(u + unknowns_.nodes, 12, c + 12);
    std::copy_n(v + unknowns_.nodes, 12, c + 24);
    cached_ = true;
  }
  return states_;
}

void WheelsetContacts::add_forces(const double* u, const double* v, double* force) {
  const auto& all = states(u, v);
  for (int k = 0; k < n_wheelset_contacts; ++k) {
    double wheelset[6], node[3];
    WheelRailContact::internal_forces(all[k], kinematics(k, u, v), wheelset, node);
    for (int i = 0; i < 6; ++i)
      force[unknowns_.wheelset + i] += wheelset[i];
    for (int i = 0; i < 3; ++i)
      force[unknowns_.nodes + 3 * k + i] += node[i];
  }
}

template <class Add>
void WheelsetContacts::for_each_tangent_entry(const double* u, const double* v, Add&& add) {
  const auto& all = states(u, v);
  for (int k = 0; k < n_wheelset_contacts; ++k) {
    if (!all[k].active)
      continue;
    double kt[81], ct[81];
    contacts_[k].tangent(kinematics(k, u, v), all[k], kt, ct);
    // The element's unknowns 0..5 are the wheelset's, 6..8 the node's.
    Eigen::Index global[9];
    for (int i = 0; i < 9; ++i)
      global[i] = static_cast<Eigen::Index>(i < 6 ? unknowns_.wheelset + i
                                                  : unknowns_.nodes + 3 * k + (i - 6));
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j)
        add(global[i], global[j], kt[i * 9 + j], ct[i * 9 + j]);
  }
}

void WheelsetContacts::add_tangent(const double* u, const double* v, Eigen::MatrixXd& stiffness,
                                   Eigen::MatrixXd& damping) {
  for_each_tangent_entry(u, v, [&](Eigen::Index i, Eigen::Index j, double k, double c) {
    stiffness(i, j) += k;
    damping(i, j) += c;
  });
}

void WheelsetContacts::add_tangent_matrix(const double* u, const double* v, double stiffness_scale,
                                          double damping_scale, Eigen::MatrixXd& matrix) {
  for_each_tangent_entry(u, v, [&](Eigen::Index i, Eigen::Index j, double k, double c) {
    matrix(i, j) += stiffness_scale * k + damping_scale * c;
  });
}

}  // namespace railfe

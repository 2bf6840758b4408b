#include "contact/geometry/profile_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railfe {

namespace {

class SplineCurve final : public ProfileCurve {
 public:
  explicit SplineCurve(const std::vector<Vec2>& points) {
    const std::size_t n = points.size();
    if (n < 3)
      throw std::invalid_argument("a spline profile needs at least 3 points");
    knots_.assign(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
      const double chord = std::hypot(points[i].y - points[i - 1].y, points[i].z - points[i - 1].z);
      if (!(chord > 0))
        throw std::invalid_argument("a spline profile needs distinct consecutive points");
      knots_[i] = knots_[i - 1] + chord;
    }
    y_.resize(n);
    z_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      y_[i] = points[i].y;
      z_[i] = points[i].z;
    }
    my_ = second_derivatives(y_);
    mz_ = second_derivatives(z_);
  }

  CurveDerivatives at(double s) const override {
    const std::size_t n = knots_.size();
    if (s < knots_.front())
      return extrapolated(0, s);
    if (s > knots_.back())
      return extrapolated(n - 1, s);
    std::size_t i = static_cast<std::size_t>(std::upper_bound(knots_.begin(), knots_.end(), s) -
                                             knots_.begin());
    i = std::clamp<std::size_t>(i, 1, n - 1) - 1;
    CurveDerivatives c;
    evaluate(y_, my_, i, s, c.p.y, c.d1.y, c.d2.y, c.d3.y);
    evaluate(z_, mz_, i, s, c.p.z, c.d1.z, c.d2.z, c.d3.z);
    return c;
  }
  double begin() const override { return knots_.front(); }
  double end() const override { return knots_.back(); }

 private:
  // Natural spline: zero second derivative at both ends; the tridiagonal system by Thomas.
  std::vector<double> second_derivatives(const std::vector<double>& f) const {
    const std::size_t n = f.size();
    std::vector<double> m(n, 0.0), diag(n, 1.0), rhs(n, 0.0), upper(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double h0 = knots_[i] - knots_[i - 1], h1 = knots_[i + 1] - knots_[i];
      const double lower = h0 / 6;
      diag[i] = (h0 + h1) / 3;
      upper[i] = h1 / 6;
      rhs[i] = (f[i + 1] - f[i]) / h1 - (f[i] - f[i - 1]) / h0;
      // Eliminate the lower entry with the previous row.
      const double factor = lower / diag[i - 1];
      diag[i] -= factor * upper[i - 1];
      rhs[i] -= factor * rhs[i - 1];
    }
    for (std::size_t i = n - 1; i-- > 1;)
      m[i] = (rhs[i] - upper[i] * m[i + 1]) / diag[i];
    return m;
  }

  void evaluate(const std::vector<double>& f, const std::vector<double>& m, std::size_t i, double s,
                double& value, double& d1, double& d2, double& d3) const {
    const double h = knots_[i + 1] - knots_[i];
    const double a = (knots_[i + 1] - s) / h, b = (s - knots_[i]) / h;
    value =
        a * f[i] + b * f[i + 1] + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6;
    d1 =
        (f[i + 1] - f[i]) / h - (3 * a * a - 1) * h / 6 * m[i] + (3 * b * b - 1) * h / 6 * m[i + 1];
    d2 = a * m[i] + b * m[i + 1];
    d3 = (m[i + 1] - m[i]) / h;
  }

  CurveDerivatives extrapolated(std::size_t end_knot, double s) const {
    CurveDerivatives c = at(knots_[end_knot]);
    const double ds = s - knots_[end_knot];
    c.p = {c.p.y + ds * c.d1.y, c.p.z + ds * c.d1.z};
    c.d2 = c.d3 = {0, 0};
    return c;
  }

  std::vector<double> knots_, y_, z_, my_, mz_;
};

class ArcCurve final : public ProfileCurve {
 public:
  ArcCurve(Vec2 centre, double radius, double angle_begin, double angle_end)
      : centre_(centre),
        radius_(radius),
        angle_begin_(angle_begin),
        direction_(angle_end >= angle_begin ? 1.0 : -1.0),
        length_(radius * std::abs(angle_end - angle_begin)) {
    if (!(radius > 0))
      throw std::invalid_argument("an arc profile needs a positive radius");
  }
  CurveDerivatives at(double s) const override {
    const double phi = angle_begin_ + direction_ * s / radius_;
    const double c = std::cos(phi), sn = std::sin(phi), w = direction_ / radius_;
    CurveDerivatives d;
    d.p = {centre_.y + radius_ * c, centre_.z + radius_ * sn};
    d.d1 = {-sn * direction_, c * direction_};
    d.d2 = {-c * w * direction_, -sn * w * direction_};
    d.d3 = {sn * w * w * direction_, -c * w * w * direction_};
    return d;
  }
  double begin() const override { return 0; }
  double end() const override { return length_; }

 private:
  Vec2 centre_;
  double radius_, angle_begin_, direction_, length_;
};

class LineCurve final : public ProfileCurve {
 public:
  LineCurve(Vec2 from, Vec2 to) : from_(from), length_(std::hypot(to.y - from.y, to.z - from.z)) {
    if (!(length_ > 0))
      throw std::invalid_argument("a line profile needs two distinct end points");
    unit_ = {(to.y - from.y) / length_, (to.z - from.z) / length_};
  }
  CurveDerivatives at(double s) const override {
    return {{from_.y + s * unit_.y, from_.z + s * unit_.z}, unit_, {0, 0}, {0, 0}};
  }
  double begin() const override { return 0; }
  double end() const override { return length_; }

 private:
  Vec2 from_, unit_;
  double length_;
};

class PlacedCurve final : public ProfileCurve {
 public:
  PlacedCurve(std::shared_ptr<const ProfileCurve> curve, const Placement& placement)
      : curve_(std::move(curve)),
        placement_(placement),
        c_(std::cos(placement.angle)),
        s_(std::sin(placement.angle)) {}
  CurveDerivatives at(double s) const override {
    const bool reverse = placement_.reverse;
    const double local = reverse ? curve_->begin() + curve_->end() - s : s;
    const CurveDerivatives c = curve_->at(local);
    const double sign = reverse ? -1.0 : 1.0;
    CurveDerivatives d;
    d.p = map(c.p);
    d.p.y += placement_.offset.y;
    d.p.z += placement_.offset.z;
    d.d1 = scaled(map(c.d1), sign);
    d.d2 = map(c.d2);
    d.d3 = scaled(map(c.d3), sign);
    return d;
  }
  double begin() const override { return curve_->begin(); }
  double end() const override { return curve_->end(); }

 private:
  Vec2 map(Vec2 v) const {
    const double y = placement_.mirror_y ? -v.y : v.y;
    return {c_ * y - s_ * v.z, s_ * y + c_ * v.z};
  }
  static Vec2 scaled(Vec2 v, double f) { return {f * v.y, f * v.z}; }

  std::shared_ptr<const ProfileCurve> curve_;
  Placement placement_;
  double c_, s_;
};

}  // namespace

double signed_curvature(const ProfileCurve& curve, double s) {
  const CurveDerivatives c = curve.at(s);
  return signed_curvature(c.d1, c.d2);
}

double signed_curvature(Vec2 d1, Vec2 d2) {
  const double speed = std::hypot(d1.y, d1.z);
  return (d1.y * d2.z - d1.z * d2.y) / (speed * speed * speed);
}

std::unique_ptr<ProfileCurve> spline_curve(const std::vector<std::array<double, 2>>& points) {
  std::vector<Vec2> converted;
  for (const auto& p : points)
    converted.push_back({p[0], p[1]});
  return spline_curve(converted);
}

std::unique_ptr<ProfileCurve> spline_curve(const std::vector<Vec2>& points) {
  return std::make_unique<SplineCurve>(points);
}

std::unique_ptr<ProfileCurve> arc_curve(Vec2 centre, double radius, double angle_begin,
                                        double angle_end) {
  return std::make_unique<ArcCurve>(centre, radius, angle_begin, angle_end);
}

std::unique_ptr<ProfileCurve> line_curve(Vec2 from, Vec2 to) {
  return std::make_unique<LineCurve>(from, to);
}

std::unique_ptr<ProfileCurve> placed_curve(std::shared_ptr<const ProfileCurve> curve,
                                           const Placement& placement) {
  return std::make_unique<PlacedCurve>(std::move(curve), placement);
}

CurveJets curve_jets(const ProfileCurve& curve, double s) {
  const CurveDerivatives c = curve.at(s);
  return {{c.p.y, c.d1.y, c.d2.y},
          {c.p.z, c.d1.z, c.d2.z},
          {c.d1.y, c.d2.y, c.d3.y},
          {c.d1.z, c.d2.z, c.d3.z}};
}

}  // namespace railfe

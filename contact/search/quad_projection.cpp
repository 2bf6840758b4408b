#include "contact/search/quad_projection.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "framework/base/error.hpp"

namespace railfe {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 minus(const double* a, const double* b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The face as S(xi, eta) = center + xi·along_xi + eta·along_eta + xi·eta·twist (the shape
// functions regrouped), so its derivatives are one multiply-add each.
struct Bilinear {
  Vec3 center, along_xi, along_eta, twist;

  explicit Bilinear(const std::array<const double*, 4>& c) {
    for (int d = 0; d < 3; ++d) {
      center[d] = 0.25 * (c[0][d] + c[1][d] + c[2][d] + c[3][d]);
      along_xi[d] = 0.25 * (-c[0][d] + c[1][d] + c[2][d] - c[3][d]);
      along_eta[d] = 0.25 * (-c[0][d] - c[1][d] + c[2][d] + c[3][d]);
      twist[d] = 0.25 * (c[0][d] - c[1][d] + c[2][d] - c[3][d]);
    }
  }
  Vec3 at(double xi, double eta) const {
    Vec3 s;
    for (int d = 0; d < 3; ++d)
      s[d] = center[d] + xi * along_xi[d] + eta * along_eta[d] + xi * eta * twist[d];
    return s;
  }
  // S(xi, eta) − x, given offset = x − centre.
  Vec3 from_centre(double xi, double eta, const Vec3& offset) const {
    Vec3 r;
    for (int d = 0; d < 3; ++d)
      r[d] = xi * along_xi[d] + eta * along_eta[d] + xi * eta * twist[d] - offset[d];
    return r;
  }
  Vec3 d_xi(double eta) const {
    return {along_xi[0] + eta * twist[0], along_xi[1] + eta * twist[1],
            along_xi[2] + eta * twist[2]};
  }
  Vec3 d_eta(double xi) const {
    return {along_eta[0] + xi * twist[0], along_eta[1] + xi * twist[1],
            along_eta[2] + xi * twist[2]};
  }
};

struct Candidate {
  double xi = 0, eta = 0, distance_squared = std::numeric_limits<double>::infinity();
  Vec3 point{};
};

// Newton on the stationarity of ½|S − x|² from (xi, eta). The full Hessian has the term
// twist·(S − x), which makes it indefinite far on the concave side of a warped face; then the
// step is Gauss–Newton's (always a descent direction). A point that converges outside the box,
// or to a saddle, is no interior minimum: the edges then hold the nearest point. \p offset is
// x − centre, so that the residual is computed from small numbers (a face of 1 mm at 1 m from
// the origin would otherwise leave 1e-13 of noise in the natural coordinates).
bool interior_minimum(const Bilinear& face, const Vec3& offset, double xi, double eta,
                      Candidate& found, int& iterations) {
  constexpr int kMaxIterations = 30;
  constexpr double kStepTolerance = 1e-14;
  constexpr double kRoundoffStep = 1e-9;  // a step this small at the bound is round-off
  constexpr double kLeaveBox = 3.0;       // beyond this the iterate is not coming back
  double step = 0;
  for (int iteration = 1;; ++iteration) {
    ++iterations;
    const Vec3 r = face.from_centre(xi, eta, offset);
    const Vec3 t_xi = face.d_xi(eta), t_eta = face.d_eta(xi);
    const double g_xi = dot(t_xi, r), g_eta = dot(t_eta, r);
    const double h_xixi = dot(t_xi, t_xi), h_etaeta = dot(t_eta, t_eta);
    double h_xieta = dot(t_xi, t_eta) + dot(face.twist, r);
    double det = h_xixi * h_etaeta - h_xieta * h_xieta;
    if (!(det > 1e-12 * h_xixi * h_etaeta)) {
      h_xieta = dot(t_xi, t_eta);
      det = h_xixi * h_etaeta - h_xieta * h_xieta;
      if (!(det > 0))
        return false;
    }
    const double step_xi = -(h_etaeta * g_xi - h_xieta * g_eta) / det;
    const double step_eta = -(h_xixi * g_eta - h_xieta * g_xi) / det;
    xi += step_xi;
    eta += step_eta;
    step = std::abs(step_xi) + std::abs(step_eta);
    if (!(std::abs(xi) < kLeaveBox && std::abs(eta) < kLeaveBox))
      return false;
    if (step < kStepTolerance)
      break;
    if (iteration == kMaxIterations) {
      if (step < kRoundoffStep)
        break;
      return false;
    }
  }
  if (std::abs(xi) > 1 || std::abs(eta) > 1)
    return false;
  // A local minimum needs the full Hessian positive definite there.
  const Vec3 r = face.from_centre(xi, eta, offset);
  const Vec3 t_xi = face.d_xi(eta), t_eta = face.d_eta(xi);
  const double h_xieta = dot(t_xi, t_eta) + dot(face.twist, r);
  if (!(dot(t_xi, t_xi) * dot(t_eta, t_eta) - h_xieta * h_xieta >= 0))
    return false;
  found = {xi, eta, dot(r, r), face.at(xi, eta)};
  return true;
}

// Whether the distance may have several local minima inside the face. The Hessian of ½|S − x|²
// is JᵀJ plus the twist times the residual r in its off-diagonal, so it is positive definite on
// the whole box, and the minimum unique, when |twist|·max|r| < λmin(JᵀJ). The area vector
// S_xi × S_eta is affine in (xi, eta), so its component along the centre normal is smallest at
// a corner; |S_xi|² + |S_eta|² is convex, so largest at a corner; their quotient bounds λmin.
bool may_have_several_minima(const Bilinear& face, const Vec3& offset) {
  const Vec3 centre_normal = cross(face.along_xi, face.along_eta);
  const double centre_area = std::sqrt(dot(centre_normal, centre_normal));
  if (!(centre_area > 0))
    return true;
  double smallest_area = std::numeric_limits<double>::infinity(), largest_metric = 0;
  for (const double xi : {-1.0, 1.0})
    for (const double eta : {-1.0, 1.0}) {
      const Vec3 t_xi = face.d_xi(eta), t_eta = face.d_eta(xi);
      smallest_area = std::min(smallest_area, dot(cross(t_xi, t_eta), centre_normal) / centre_area);
      largest_metric = std::max(largest_metric, dot(t_xi, t_xi) + dot(t_eta, t_eta));
    }
  if (!(smallest_area > 0))
    return true;
  const double twist = std::sqrt(dot(face.twist, face.twist));
  const double reach = std::sqrt(dot(offset, offset)) +
                       std::sqrt(dot(face.along_xi, face.along_xi)) +
                       std::sqrt(dot(face.along_eta, face.along_eta)) + twist;
  return twist * reach >= smallest_area * smallest_area / largest_metric;
}

// The nearest point of the straight edge from corner a to corner b, in natural coordinates
// (xi, eta) = start + s·direction for s in [0, 1].
Candidate edge_nearest(const double* a, const double* b, double xi0, double eta0, double dxi,
                       double deta, const double* x) {
  const Vec3 edge = minus(b, a), to_x = minus(x, a);
  const double length_squared = dot(edge, edge);
  double s = length_squared > 0 ? dot(to_x, edge) / length_squared : 0;
  s = s < 0 ? 0 : (s > 1 ? 1 : s);
  Candidate c;
  c.xi = xi0 + s * dxi;
  c.eta = eta0 + s * deta;
  for (int d = 0; d < 3; ++d)
    c.point[d] = a[d] + s * edge[d];
  const Vec3 r = minus(x, c.point.data());
  c.distance_squared = dot(r, r);
  return c;
}

[[noreturn]] void throw_degenerate(const std::array<const double*, 4>& c) {
  std::ostringstream message;
  message << "contact search: a master face has collapsed (no normal exists); its corners are";
  for (const double* p : c)
    message << " (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  throw RunError(message.str());
}

}  // namespace

QuadProjection project_onto_quad(const std::array<const double*, 4>& corners, const double* x) {
  const Bilinear face(corners);
  Candidate best;
  QuadProjection result;
  const Vec3 offset = minus(x, face.center.data());
  bool interior = interior_minimum(face, offset, 0, 0, best, result.iterations);
  if (may_have_several_minima(face, offset)) {
    // A strongly warped face seen from afar: start also from each quarter's centre.
    for (const double start_xi : {-0.5, 0.5})
      for (const double start_eta : {-0.5, 0.5}) {
        Candidate other;
        if (interior_minimum(face, offset, start_xi, start_eta, other, result.iterations) &&
            other.distance_squared < best.distance_squared) {
          best = other;
          interior = true;
        }
      }
  }
  // The four straight edges: 0-1 (eta = -1), 1-2 (xi = 1), 2-3 (eta = 1), 3-0 (xi = -1).
  const Candidate edges[4] = {
      edge_nearest(corners[0], corners[1], -1, -1, 2, 0, x),
      edge_nearest(corners[1], corners[2], 1, -1, 0, 2, x),
      edge_nearest(corners[2], corners[3], 1, 1, -2, 0, x),
      edge_nearest(corners[3], corners[0], -1, 1, 0, -2, x),
  };
  for (const Candidate& edge : edges) {
    // On a tie the interior point stays: it carries the exact face normal.
    if (edge.distance_squared < best.distance_squared) {
      best = edge;
      interior = false;
    }
  }
  result.xi = best.xi;
  result.eta = best.eta;
  result.point = best.point;
  result.on_boundary = !interior;
  result.distance = std::sqrt(best.distance_squared);

  const double scale = dot(face.along_xi, face.along_xi) + dot(face.along_eta, face.along_eta);
  Vec3 normal = cross(face.d_xi(best.eta), face.d_eta(best.xi));
  double length = std::sqrt(dot(normal, normal));
  if (!(length > 1e-12 * scale)) {
    // A corner collapsed onto its neighbour (a wedge's side): the normal at the centre.
    normal = cross(face.along_xi, face.along_eta);
    length = std::sqrt(dot(normal, normal));
    if (!(length > 1e-12 * scale))
      throw_degenerate(corners);
  }
  for (int d = 0; d < 3; ++d)
    result.normal[d] = normal[d] / length;
  result.gap = dot(minus(x, result.point.data()), result.normal);
  return result;
}

std::array<double, 4> quad_shape_functions(double xi, double eta) {
  return {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta), 0.25 * (1 + xi) * (1 + eta),
          0.25 * (1 - xi) * (1 + eta)};
}

}  // namespace railfe

#include "contact/geometry/conicity.hpp"

#include <cmath>
#include <limits>

namespace railfe {

double klingel_wavelength(double r0, double e, double conicity) {
  return 2 * M_PI * std::sqrt(r0 * e / conicity);
}

double equivalent_conicity(double wavelength, double e, double r0) {
  const double k = 2 * M_PI / wavelength;
  return e * r0 * k * k;
}

double regression_conicity(const std::function<double(double)>& delta_r, double amplitude,
                           int samples) {
  double sum_y = 0, sum_r = 0, sum_yy = 0, sum_yr = 0;
  for (int k = 0; k < samples; ++k) {
    const double y = amplitude * std::sin(2 * M_PI * (k + 0.5) / samples);
    const double r = delta_r(y);
    sum_y += y;
    sum_r += r;
    sum_yy += y * y;
    sum_yr += y * r;
  }
  const double n = samples;
  const double slope = (sum_yr - sum_y * sum_r / n) / (sum_yy - sum_y * sum_y / n);
  return slope / 2;
}

double kinematic_wavelength(const std::function<double(double)>& delta_r, double e, double r0,
                            double amplitude) {
  auto acceleration = [&](double y) { return -delta_r(y) / (2 * e * r0); };
  // Step from the small-amplitude wavelength estimate: 4000 steps per period.
  const double slope = delta_r(amplitude) / amplitude;
  if (!(slope > 0))
    return std::numeric_limits<double>::quiet_NaN();
  const double h = 2 * M_PI * std::sqrt(2 * e * r0 / slope) / 4000;
  double x = 0, y = amplitude, v = 0;
  int sign_changes = 0;
  double previous_v = 0;
  // Start at the positive turning point; one period ends at the second sign change of y'
  // (from negative through positive back to zero): the first is the negative turning point.
  for (int step = 0; step < 4000000; ++step) {
    const double k1y = v, k1v = acceleration(y);
    const double k2y = v + 0.5 * h * k1v, k2v = acceleration(y + 0.5 * h * k1y);
    const double k3y = v + 0.5 * h * k2v, k3v = acceleration(y + 0.5 * h * k2y);
    const double k4y = v + h * k3v, k4v = acceleration(y + h * k3y);
    const double y_next = y + h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y);
    const double v_next = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (step > 0 && (previous_v < 0) != (v_next < 0) && v_next != 0) {
      ++sign_changes;
      if (sign_changes == 2) {
        // Linear interpolation of the zero of y' within the step.
        return x + h * v / (v - v_next);
      }
    }
    previous_v = v_next;
    x += h;
    y = y_next;
    v = v_next;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace railfe

#pragma once
/// \file
/// Equivalent conicity as EN 15302 defines it through the kinematic (Klingel) motion of a free
/// wheelset: the lateral displacement y(x) obeys y'' + dr(y) / (2 e r0) = 0, where dr(y) is the
/// rolling radius difference (right minus left) at shift y, e half the distance between the
/// contact points and r0 the centred rolling radius. For an amplitude y_hat the motion has a
/// wavelength lambda, and the equivalent conicity is the cone's that has the same wavelength:
/// tan(gamma_e) = e r0 (2 pi / lambda)^2.

#include <functional>

namespace railfe {

/// Klingel's wavelength of a conical wheelset: 2 pi sqrt(r0 e / gamma) (m).
double klingel_wavelength(double r0, double e, double conicity);

/// Wavelength of the kinematic motion with amplitude \p amplitude (m, the positive turning
/// point) under the rolling radius difference \p delta_r (m as a function of m), by integrating
/// the equation of motion over one period (fourth-order Runge-Kutta). NaN when the motion is not
/// oscillatory (dr does not restore the wheelset).
double kinematic_wavelength(const std::function<double(double)>& delta_r, double e, double r0,
                            double amplitude);

/// Equivalent conicity of a wavelength: e r0 (2 pi / lambda)^2.
double equivalent_conicity(double wavelength, double e, double r0);

/// Equivalent conicity by linear regression of the rolling radius difference (EN 15302:2008+A1,
/// Annex C): dr is sampled along a harmonic motion y = y_hat sin(phi), \p samples phases evenly
/// spaced over one period (so each shift counts as long as the wheelset dwells there), a straight
/// line is fitted by least squares and tan(gamma_e) is half its slope. It needs no e or r0 and
/// stays finite where dr jumps (flange contact within the amplitude), which the kinematic
/// wavelength does not smooth.
double regression_conicity(const std::function<double(double)>& delta_r, double amplitude,
                           int samples = 2000);

}  // namespace railfe

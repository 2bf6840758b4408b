#pragma once
/// \file
/// Names vibration modes of axisymmetric bodies (railway wheels, rings) the way the railway
/// literature does: a family (axial = out of plane; radial or circumferential = in plane), the
/// number of nodal diameters n and the number of nodal circles m, written (m, n).
///
/// Method: the mode is written in cylindrical components (u_r, u_θ, u_a) about the body's axis.
/// n is the circumferential Fourier harmonic carrying most of the rim's power; the family is the
/// displacement component carrying most of the rim's energy; m is the number of sign changes of
/// the family's component along a radial line of the web at an angle of maximum amplitude.
/// Modes that fit no single label are reported as ambiguous with a note, never forced.
///
/// Plain C++17, no MPI or Trilinos: the caller gathers the mode shape on one process first.

#include <array>
#include <string>
#include <vector>

namespace railfe {

/// The axis of revolution of the body.
struct AxisymmetricFrame {
  /// Any point on the axis (m).
  std::array<double, 3> origin{0, 0, 0};
  /// Direction of the axis; any non-zero length (it is normalised). Angles θ are measured, right
  /// handed about it, from the projection of the global x, y or z axis least aligned with it
  /// (the lowest index on ties: x for the default y axis).
  std::array<double, 3> axis{0, 1, 0};
};

/// Thresholds of the classification. The defaults suit a railway wheel meshed with a
/// cyclic-symmetric mesh (every ring of nodes of equal radius and axial position is evenly
/// spaced in angle), and a ring.
struct ClassifierSettings {
  /// Share (0, 1] of the radial extent, counted inward from the outer radius, whose nodes form
  /// the rim on which nodal diameters and the family are judged. 0.2 covers a wheel's rim (the
  /// outer 10–15 % of its radius) with margin; 1 uses the whole body.
  double rim_fraction = 0.2;
  /// Inner radius (m) of the radial line along which nodal circles are counted; 0 = the body's
  /// inner radius. Set it to the hub's outer radius to leave the hub out.
  double web_inner_radius = 0;
  /// Outer radius (m) of that line; 0 = the body's outer radius (the rim is then included).
  double web_outer_radius = 0;
  /// Highest harmonic (≥ 0) examined. Each ring is examined up to its own Nyquist limit (half
  /// its node count) at most; a mode with more diameters than this comes out ambiguous.
  int max_diameters = 32;
  /// Smallest share (0, 1] of the rim's power that the dominant harmonic must carry for n to be
  /// reported. Two harmonics of equal power give 0.5, so 0.6 rejects them with margin, while a
  /// mode of a cyclic-symmetric mesh is a pure harmonic (share near 1).
  double dominance = 0.6;
  /// Smallest share (0.5, 1] of the rim's energy that decides a family: out of plane vs in
  /// plane first (against all the energy), then radial vs circumferential (against the in-plane
  /// energy). Above 0.5 so that a tie is ambiguous; 0.6 still names a ring's in-plane flexure
  /// (radial share n²/(n² + 1) ≥ 0.8 for n ≥ 2) and leaves n = 1 (rigid in-plane translation,
  /// 0.5) ambiguous.
  double family_dominance = 0.6;
  /// Values on the nodal-circle line smaller than this share [0, 1) of the line's largest
  /// magnitude are treated as zero, so that noise near a node line adds no circles. Small
  /// because a wheel's hub moves little: a true lobe there can be a few percent of the rim's.
  double noise_fraction = 0.05;
  /// Positions closer than this share (> 0) of the body's size are taken as equal when nodes
  /// are grouped into rings and through the thickness. Cyclic meshes agree to round-off.
  double relative_tolerance = 1e-6;
};

/// The label of one mode and the figures behind it.
struct ModeClass {
  /// "axial", "radial", "circumferential", or "ambiguous" (see note).
  std::string family = "ambiguous";
  /// n, or -1 when no harmonic dominates (judged independently of the family).
  int nodal_diameters = -1;
  /// m, or -1 when n or the family is ambiguous (no single line and component to follow), or
  /// no web node lies on the line.
  int nodal_circles = -1;
  /// Share of the rim's power carried by the dominant harmonic (whether or not it dominates).
  double diameter_share = 0;
  /// Share of the rim's energy in u_a (out of plane).
  double axial_share = 0;
  /// Share of the rim's energy in u_r.
  double radial_share = 0;
  /// Share of the rim's energy in u_θ.
  double circumferential_share = 0;
  /// One angle (rad, in [0, π/n)) where the family's component (or, for an ambiguous family,
  /// the strongest component in harmonic n) is largest in magnitude; the others are this plus
  /// multiples of π/n. 0 when n is 0 or ambiguous.
  double phase_angle = 0;
  /// Why something is ambiguous, and warnings (skipped rings); empty when all went well.
  std::string note;
};

/// Classifies the mode shape \p displacements (one per node, any consistent unit) of the body
/// whose nodes are at \p points (m), gathered on one process, about \p frame.
///
/// Limits: nodes on the axis are ignored; rings (nodes of equal radius and axial position) with
/// fewer than 3 nodes are skipped with a note; rings need not be evenly spaced (each node is
/// weighted by its angular share), but a sector model (no full revolution) is not supported.
/// Nodes through the thickness are averaged only where they share a radius, so on a sloped or
/// curved web each node counts on its own. A zero mode, or one still on the rim, is ambiguous.
///
/// Throws std::invalid_argument when the sizes differ, the axis is zero, a value is not finite
/// or a setting is out of range.
ModeClass classify_mode(const std::vector<std::array<double, 3>>& points,
                        const std::vector<std::array<double, 3>>& displacements,
                        const AxisymmetricFrame& frame, const ClassifierSettings& settings = {});

}  // namespace railfe

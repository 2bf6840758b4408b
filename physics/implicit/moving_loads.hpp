#pragma once
/// \file
/// Moving loads of an implicit step: a force of fixed direction travelling along a beam path at
/// constant speed (Frýba's moving force), applied as the work-consistent nodal load Nᵀ P of the
/// element beneath it (beam_interpolation.hpp). Off the path (before it arrives, after it
/// leaves) the load is zero.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/assembly/dof_map.hpp"
#include "framework/deck/expression.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "physics/common/structural_sections.hpp"
#include "physics/implicit/moving_contact.hpp"

namespace railfe {

/// One moving load as the deck gives it.
struct MovingLoadSpec {
  std::string name;                 ///< its deck name
  std::vector<std::string> blocks;  ///< the beam blocks of its path
  double start = 0;                 ///< arc length at t = 0 (m)
  double speed = 0;                 ///< ds/dt (m/s)
  std::array<double, 3> force{};    ///< P (N)
  std::string function = "1";       ///< scale of P as a function of t
};

/// Adds the Moving loads sublist to an implicit step's spec.
void add_moving_load_parameters(ParameterSpec& spec);

/// Reads the Moving loads of a validated step list.
std::vector<MovingLoadSpec> read_moving_loads(const Teuchos::ParameterList& step,
                                              const std::string& deck, const std::string& path);

/// The moving loads of a run on the owned DOFs of a 6-DOF DofMap.
class MovingLoads {
 public:
  /// Builds the paths of \p specs on the beams of \p mesh (sections from \p sections), the
  /// load going to \p unknown(node, component) of each DOF (−1: none here). Throws InputError
  /// naming \p deck and the parameter under \p path for a bad path.
  MovingLoads(const std::vector<MovingLoadSpec>& specs, const Mesh& mesh,
              const SectionTable& sections, const std::function<long(GlobalIndex, int)>& unknown,
              const std::string& deck, const std::string& path);

  /// Adds every load at \p time to \p force (indexed by the unknowns).
  void add(double time, double* force) const;
  /// Whether there are any.
  bool empty() const { return loads_.empty(); }

 private:
  struct Load {
    BeamPath path;
    double start, speed;
    Eigen::Vector3d force;
    Expression scale;
  };
  std::vector<Load> loads_;
};

}  // namespace railfe

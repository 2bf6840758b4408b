#pragma once
/// \file
/// The direct method in a deck: an implicit step with Moving contacts. The model's matrices,
/// assembled distributed, are gathered on rank 0 and split into the vehicle (the nodes joined
/// by elements to the contact nodes: a small dense block) and the structure (everything else:
/// sparse, factored once by CHOLMOD); HHT-α with the constraints runs there with the block or
/// the monolithic saddle-point solver (framework/solvers/saddle_point_solvers.hpp), and the state
/// is scattered back to every rank after each step, so outputs are those of any implicit step.
/// The structure's factorization runs on rank 0 in every case (CHOLMOD is not distributed), so
/// integrating there costs the other ranks nothing they could have done.

#include <memory>
#include <string>
#include <vector>

#include "framework/assembly/dof_map.hpp"
#include "framework/deck/expression.hpp"
#include "physics/common/structural_sections.hpp"
#include "physics/implicit/implicit_settings.hpp"
#include "physics/implicit/implicit_stepper.hpp"
#include "physics/implicit/implicit_system.hpp"
#include "physics/implicit/moving_contact_settings.hpp"
#include "physics/implicit/moving_loads.hpp"

namespace railfe {

class CsvWriter;

/// What the constrained stepper is built from.
struct ConstrainedSetup {
  const DofMap* dofs = nullptr;                               ///< the model's DOFs
  const LinearModelMatrices* matrices = nullptr;              ///< K, M, C and the load at scale 1
  const std::vector<LocalIndex>* fixed = nullptr;             ///< owned DOFs held at zero
  std::string load_function;                                  ///< s(t)
  const std::vector<MovingLoadSpec>* moving_loads = nullptr;  ///< loads travelling on beams
  const std::vector<MovingContactSpec>* contacts = nullptr;   ///< the vehicle points
  const SectionTable* sections = nullptr;                     ///< beams of the paths
  const ImplicitSettings* settings = nullptr;                 ///< scheme, Newton, damping
  std::string solver = "block";                               ///< "block" or "monolithic"
  std::string deck;                                           ///< for messages
  std::string path;                                           ///< "Steps/<name>"
};

/// HHT-α with moving constraints on rank 0 (see the file comment).
class ConstrainedStepper : public ImplicitStepper {
 public:
  /// Gathers and splits the model, builds the paths and the solver (collective). Throws
  /// InputError when a vehicle is joined to the structure by elements.
  explicit ConstrainedStepper(const ConstrainedSetup& setup);
  ~ConstrainedStepper() override;

  void initialize(double time, double* u, double* v, double* a) override;
  int advance(double time, double dt, double* u, double* v, double* a) override;
  NewtonStatistics statistics() const override;
  std::size_t n_cut_backs() const override;

  /// Opens <step>_contacts.csv (time, then position and vertical force of each contact) at
  /// \p path (rank 0 writes).
  void open_contact_file(const std::string& path);
  /// Writes the contact row of the last step (rank 0).
  void write_contacts(double time);
  /// Writes the separations and engagements to \p path and returns how many (collective).
  double write_events(const std::string& path);
  /// Unknowns of the structure and of the vehicle (rank 0; 0 elsewhere).
  std::size_t n_structure() const;
  /// Unknowns of the vehicle (rank 0; 0 elsewhere).
  std::size_t n_vehicle() const;
  /// CHOLMOD factorizations of the structure so far (collective; rank 0's count).
  double structure_factorizations() const;

 private:
  struct Root;
  // Copies rank 0's unknowns into the distributed arrays (collective).
  void scatter(double* u, double* v, double* a);
  // Copies the distributed arrays into rank 0's unknowns (collective).
  void gather(const double* u, const double* v, const double* a);
  // Every rank throws what rank 0 found ('' = nothing).
  void share(const std::string& problem, bool not_converged) const;

  ConstrainedSetup setup_;
  std::unique_ptr<Root> root_;
  std::unique_ptr<CsvWriter> contact_file_;
};

}  // namespace railfe

#pragma once
/// \file
/// Preconditioners for the Krylov solvers: MueLu algebraic multigrid (plain or smoothed
/// aggregation) and Ifpack2 one-level methods.

#include <string>

#include "framework/solvers/linear_solver.hpp"

namespace railfe {

/// Builds the preconditioner called \p kind ("muelu", "muelu-sa", "ilu", "jacobi"; "none" gives
/// null) for
/// \p A (collective). MueLu uses the node coordinates and near null space of \p traits.
Teuchos::RCP<TpetraOperator> make_preconditioner(const std::string& kind,
                                                 const Teuchos::RCP<const TpetraMatrix>& A,
                                                 const ProblemTraits& traits);

/// Human-readable name of preconditioner \p kind, for reports.
std::string preconditioner_description(const std::string& kind);

}  // namespace railfe

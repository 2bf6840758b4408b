#pragma once
/// \file
/// Names for the Tpetra types railfe uses, from Tpetra's forward declarations only, so headers
/// that pass these objects around stay light. Debian's Trilinos 13.2 instantiates double values,
/// int local and long long global ordinals on the Serial node: the defaults.

#include <Teuchos_RCP.hpp>

#include <Tpetra_CrsGraph_fwd.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_Export_fwd.hpp>
#include <Tpetra_Import_fwd.hpp>
#include <Tpetra_Map_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>
#include <Tpetra_Operator_fwd.hpp>
#include <Tpetra_Vector_fwd.hpp>
#include "framework/base/types.hpp"

namespace railfe {

/// Distribution of global indices (DOFs) over ranks.
using TpetraMap = Tpetra::Map<>;
/// Distributed sparse matrix of doubles.
using TpetraMatrix = Tpetra::CrsMatrix<double>;
/// Distributed sparse graph.
using TpetraGraph = Tpetra::CrsGraph<>;
/// Distributed vector of doubles.
using TpetraVector = Tpetra::Vector<double>;
/// Distributed block of vectors.
using TpetraMultiVector = Tpetra::MultiVector<double>;
/// Anything that applies y = A x.
using TpetraOperator = Tpetra::Operator<double>;
/// Communication plan from a one-to-one map to an overlapping one.
using TpetraImport = Tpetra::Import<>;
/// Communication plan from an overlapping map to a one-to-one one.
using TpetraExport = Tpetra::Export<>;

}  // namespace railfe

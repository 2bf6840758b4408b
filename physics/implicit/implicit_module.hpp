#pragma once
/// \file
/// The implicit module: linear structural dynamics by HHT-α (or Newmark) with Newton iterations
/// (framework/time/hht_integrator.hpp), a step cut-back that halves Δt and reports it, Rayleigh
/// damping, and the effective matrix factored once when nothing changes (CHOLMOD by default).
/// Starts from rest or from a statics step's displacements; writes histories, measurements,
/// the energy balance, Newton statistics and Exodus snapshots (implicit_output.hpp).

#include "framework/app/module.hpp"

namespace railfe {

/// The module's registration record.
ModuleDescriptor implicit_module();

}  // namespace railfe

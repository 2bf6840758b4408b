#pragma once
/// \file
/// The deck's Contact sublist of the modules that run wheelsets on the implicit contact element
/// ("wheelset dynamics", "vehicle dynamics"): its valid parameters and the element settings
/// they give.

#include <Teuchos_ParameterList.hpp>

#include <string>

#include "contact/enforcement/wheel_rail_contact.hpp"
#include "framework/deck/parameter_spec.hpp"

namespace railfe {

/// Valid parameters of the Contact sublist.
ParameterSpec contact_parameters();

/// The contact element's settings from the validated Contact sublist of \p step.
WheelRailContactSettings contact_settings(const Teuchos::ParameterList& step);

/// Throws InputError naming \p source and \p path (the step's) for Contact settings that
/// contradict each other (an offline table without the lookup table).
void check_contact_parameters(const Teuchos::ParameterList& step, const std::string& source,
                              const std::string& path);

}  // namespace railfe

#pragma once
/// \file
/// The deck's Contact sublist of the modules that run wheelsets on the implicit contact element
/// ("wheelset dynamics", "vehicle dynamics"): its valid parameters and the element settings
/// they give.

#include <Teuchos_ParameterList.hpp>

#include "contact/enforcement/wheel_rail_contact.hpp"
#include "framework/deck/parameter_spec.hpp"

namespace railfe {

/// Valid parameters of the Contact sublist.
ParameterSpec contact_parameters();

/// The contact element's settings from the validated Contact sublist of \p step.
WheelRailContactSettings contact_settings(const Teuchos::ParameterList& step);

}  // namespace railfe

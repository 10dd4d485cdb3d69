#pragma once
// Fixture for architecture_layers_catches_violation: a program must not include the other.
#include "dem_app/engine/body_state.hpp"

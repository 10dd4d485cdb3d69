#pragma once
// Fixture for architecture_layers_catches_violation: geometry must not include the scene.
#include "coupler_lib/scene/scene.hpp"

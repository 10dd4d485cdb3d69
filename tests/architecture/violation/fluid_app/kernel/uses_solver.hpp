#pragma once
// Fixture for architecture_layers_catches_violation: the kernel must not include the solver
// above it.
#include "fluid_app/solver/fluid_solver.hpp"

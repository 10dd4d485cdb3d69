#pragma once
// Fixture for architecture_layers_catches_violation: the contact law must not include the
// engine above it.
#include "dem_app/engine/lammps_engine.hpp"

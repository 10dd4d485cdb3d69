// Fixture for architecture_layers_catches_violation: a source in no CMake source list.

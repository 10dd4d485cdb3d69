#pragma once
// Fixture for architecture_layers_catches_violation: a folder that is in no layer.

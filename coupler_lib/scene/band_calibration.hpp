#pragma once
// The hydrodynamic radius of the HLBM band (docs/method.md, "Hydrodynamic radius
// calibration"). A body's porous band (0 < d < 1) makes the flow see a body larger than the
// true one by a distance that depends on the relaxation time and the porosity lookup, hardly on
// the body's size: the Stokes drag of a dilute periodic array of spheres, inverted through
// Sangani & Acrivos (1982), gives a_h - a = 0.84 cells at tau 0.505, 0.35 at 0.6 and -0.13 at 1
// with the nearest lookup (-1.26 at tau 3: the band lets the flow in). Removing that excess from
// the surface the fluid sees is the calibration of Ladd (1994, J. Fluid Mech. 271, part 2) for his
// bounce-back spheres. The table is measured by tools/calibrate_band.py (docs/validation.md,
// section 6), not fitted to any validation case.
#include <optional>
#include <string>

#include "coupler_lib/scene/choices.hpp"

namespace lbdem {

// Excess of the band's hydrodynamic radius over the body's, in lattice cells, at this tau for
// the lookup; interpolated linearly in ln(tau - 1/2) between the
// measured relaxation times. nullopt outside the measured range.
std::optional<double> band_radius_excess_cells(double tau, PorosityLookup lookup);

// "[0.505, 3]": the measured range of tau, for messages.
std::string band_calibration_range();

// Whether the calibrated drag was checked at this tau: tools/band_size_series.py, spheres of
// radius 3 to 9 cells over 16 poses from tau 0.52 to 1.5 (docs/method.md). Outside that range
// (inside the measured one) the table still applies, unchecked.
bool band_calibration_checked(double tau);
std::string band_calibration_checked_range();  // "[0.52, 1.5]", for messages

}  // namespace lbdem

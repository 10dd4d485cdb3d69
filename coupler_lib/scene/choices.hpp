#pragma once
// Every choice word a scene may hold, with the enum it becomes when the scene is read
// (coupler_lib/words.hpp). The schema lists each key's allowed words from these tables, so the
// words, the readers and docs/scene-reference.md cannot disagree. Shape kinds and clump methods
// sit with the shape parameters (coupler_lib/geometry/shape_params.hpp), which clump_gen shares.
#include <array>

#include "coupler_lib/words.hpp"

namespace lbdem {

// fluid.boundaries.<face>.type
enum class FaceType { periodic, wall, moving_wall, pressure };
inline constexpr WordTable<FaceType, 4> kFaceTypeWords{{{"periodic", FaceType::periodic},
                                                        {"wall", FaceType::wall},
                                                        {"moving_wall", FaceType::moving_wall},
                                                        {"pressure", FaceType::pressure}}};

// fluid.precision: the lattice's floating-point type.
enum class Precision { float32, float64 };
inline constexpr WordTable<Precision, 2> kPrecisionWords{
    {{"double", Precision::float64}, {"float", Precision::float32}}};
// fluid.output.fields.precision: the type of the field files (float by default).
inline constexpr WordTable<Precision, 2> kFilePrecisionWords{
    {{"float", Precision::float32}, {"double", Precision::float64}}};

// fluid.porosity_lookup: how a mapped node reads a shape's reference porosity
// (fluid_app/hlbm/reference_porosity.hpp describes both).
enum class PorosityLookup { trilinear, nearest };
inline constexpr WordTable<PorosityLookup, 2> kPorosityLookupWords{
    {{"nearest", PorosityLookup::nearest}, {"trilinear", PorosityLookup::trilinear}}};

// fluid.hydrodynamic_radius: nominal, the fluid sees the body's true surface (the paper's
// construction); calibrated, the surface moved inward by the band's measured
// hydrodynamic-radius excess at this tau (docs/method.md "Hydrodynamic radius calibration").
enum class HydrodynamicRadius { calibrated, nominal };
inline constexpr WordTable<HydrodynamicRadius, 2> kHydrodynamicRadiusWords{
    {{"calibrated", HydrodynamicRadius::calibrated}, {"nominal", HydrodynamicRadius::nominal}}};

// fluid.loads: how the hydrodynamic load on a body is computed (docs/method-loads.md).
enum class LoadMethod {
  penalization,       // from the momentum the penalization exchanges (conserves momentum)
  momentum_exchange,  // Galilean-invariant momentum exchange over the band's boundary links
};
inline constexpr WordTable<LoadMethod, 2> kLoadMethodWords{
    {{"penalization", LoadMethod::penalization},
     {"momentum_exchange", LoadMethod::momentum_exchange}}};

// fluid.decomposition: how the fluid lattice is split over the fluid ranks
// (fluid_app/parallel/decomposition.hpp): equal blocks, or a rectilinear grid of blocks whose
// cuts balance the weighted work of the initial bodies, and at a restart the work measured at
// the checkpoint when its imbalance exceeds fluid.rebalance_above.
enum class DecompositionKind { regular, balanced };
inline constexpr WordTable<DecompositionKind, 2> kDecompositionWords{
    {{"regular", DecompositionKind::regular}, {"balanced", DecompositionKind::balanced}}};

// fluid.validation.case: the analytic flows fluid_app checks itself against.
enum class ValidationCase { poiseuille, couette, taylor_green };
inline constexpr WordTable<ValidationCase, 3> kValidationCaseWords{
    {{"poiseuille", ValidationCase::poiseuille},
     {"couette", ValidationCase::couette},
     {"taylor_green", ValidationCase::taylor_green}}};

// Axes and planes by their letters (fluid.output slices, fluid.validation.plane, dem.walls).
inline constexpr WordTable<int, 3> kAxisWords{{{"x", 0}, {"y", 1}, {"z", 2}}};
inline constexpr WordTable<std::array<int, 2>, 3> kPlaneWords{
    {{"xy", {0, 1}}, {"yz", {1, 2}}, {"zx", {2, 0}}}};
// dem.walls[].side: whether the wall bounds the axis from below.
inline constexpr WordTable<bool, 2> kLowerSideWords{{{"lo", true}, {"hi", false}}};

// dem.dt_rule: the sphere whose Rayleigh time sets the DEM step
// (coupler_lib/scene/dem_time_step.hpp).
enum class DtRule { clump_sphere, particle };
inline constexpr WordTable<DtRule, 2> kDtRuleWords{
    {{"clump_sphere", DtRule::clump_sphere}, {"particle", DtRule::particle}}};

// coupling.wait: how a waiting side waits (coupler_lib/coupling/wait.hpp).
enum class WaitMode { backoff, blocking };
inline constexpr WordTable<WaitMode, 2> kWaitModeWords{
    {{"backoff", WaitMode::backoff}, {"blocking", WaitMode::blocking}}};

// bodies[].generate: the placement of generated bodies.
enum class BodyPattern { lattice, random };
inline constexpr WordTable<BodyPattern, 2> kBodyPatternWords{
    {{"lattice", BodyPattern::lattice}, {"random", BodyPattern::random}}};

// bodies[].format: the layout of a bodies file.
enum class BodiesFormat { csv, hdf5 };
inline constexpr WordTable<BodiesFormat, 2> kBodiesFormatWords{
    {{"csv", BodiesFormat::csv}, {"hdf5", BodiesFormat::hdf5}}};

// log_level (and --log-level): spdlog's level names.
enum class LogLevel { trace, debug, info, warn, error };
inline constexpr WordTable<LogLevel, 5> kLogLevelWords{{{"trace", LogLevel::trace},
                                                        {"debug", LogLevel::debug},
                                                        {"info", LogLevel::info},
                                                        {"warn", LogLevel::warn},
                                                        {"error", LogLevel::error}}};

}  // namespace lbdem

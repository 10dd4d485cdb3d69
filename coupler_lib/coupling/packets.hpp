#pragma once
// The two packets that cross between the binaries. Plain, fixed-layout structs (no
// pointers), sent as raw bytes; `version` lets the receiver reject a peer built from a
// different protocol.
#include <cstdint>
#include <type_traits>

namespace lbdem {

inline constexpr std::uint32_t kProtocolVersion = 1;

// DEM -> fluid: where a body is and how it moves (SI units, space frame).
struct BodyState {
  std::uint32_t version = kProtocolVersion;
  std::int32_t shape = 0;      // index into the scene's shape catalogue
  std::int64_t id = 0;         // body id, 0-based, stable for the whole run
  std::int64_t step = 0;       // fluid step this state belongs to
  double x[3] = {0, 0, 0};     // centre of mass, m
  double q[4] = {1, 0, 0, 0};  // orientation (w, x, y, z): shape frame -> space frame
  double v[3] = {0, 0, 0};     // velocity, m/s
  double w[3] = {0, 0, 0};     // angular velocity, rad/s (space frame)
};

// fluid -> DEM: hydrodynamic force and torque (about the centre of mass) on a body, SI.
// A fluid rank sends the partial sum over its own nodes; the owning DEM rank reduces them.
struct BodyLoad {
  std::uint32_t version = kProtocolVersion;
  std::int32_t pad = 0;
  std::int64_t id = 0;
  std::int64_t step = 0;
  double f[3] = {0, 0, 0};  // N
  double t[3] = {0, 0, 0};  // N m
};

static_assert(std::is_trivially_copyable_v<BodyState> && sizeof(BodyState) == 128);
static_assert(std::is_trivially_copyable_v<BodyLoad> && sizeof(BodyLoad) == 72);

}  // namespace lbdem

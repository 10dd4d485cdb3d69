#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "coupler_lib/coupling/compare.hpp"
#include "coupler_lib/coupling/recording.hpp"
#include "coupler_lib/coupling/reduce.hpp"

namespace lbdem {
namespace {

std::vector<BodyState> states(std::int64_t step, int n) {
  std::vector<BodyState> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    BodyState& s = v[static_cast<size_t>(i)];
    s.id = i;
    s.step = step;
    s.shape = i % 2;
    for (int d = 0; d < 3; ++d) {
      s.x[d] = std::sqrt(2.0) * (i + d) + 1e-300 * step;
      s.v[d] = -1.0 / (3.0 + i + d);
      s.w[d] = std::nextafter(0.1 * d, 1.0);
    }
    s.q[0] = std::cos(0.1 * i);
    s.q[3] = std::sin(0.1 * i);
  }
  return v;
}

std::vector<BodyLoad> loads(std::int64_t step, int n) {
  std::vector<BodyLoad> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    v[static_cast<size_t>(i)].id = i;
    v[static_cast<size_t>(i)].step = step;
    for (int d = 0; d < 3; ++d) {
      v[static_cast<size_t>(i)].f[d] = std::exp(-i - d) * (step + 1);
      v[static_cast<size_t>(i)].t[d] = std::numeric_limits<double>::denorm_min() * (i + 1);
    }
  }
  return v;
}

// Unique per process: several builds may run this test at the same time.
std::string temp_file(const char* name) {
  return (std::filesystem::temp_directory_path() /
          (std::string(name) + "." + std::to_string(::getpid()) + ".h5"))
      .string();
}

TEST(Recording, RoundTripIsBitExact) {
  const std::string path = temp_file("lbdem_recording_test");
  RecordingInfo info;
  info.scene_hash = 0xfedcba9876543210ull;
  info.scene_file = "scene.yaml";
  info.fluid_ranks = 3;
  info.dem_ranks = 2;
  info.layout.domain.hi = {1, 2, 3};
  info.layout.periodic = {true, false, true};
  info.layout.boxes = {info.layout.domain};
  info.layout.shape_radius = {0.1, 0.2};
  info.layout.margin = 0.05;
  {
    RecordingWriter w(path, info);
    for (std::int64_t step = 0; step < 1500; ++step) {  // more rows than one chunk
      w.append_states(step, states(step, 3));
      w.append_loads(step, loads(step, static_cast<int>(step % 4)));
    }
  }
  const RecordingReader r(path);
  EXPECT_EQ(r.info().scene_hash, info.scene_hash);
  EXPECT_EQ(r.info().scene_file, "scene.yaml");
  EXPECT_EQ(r.info().fluid_ranks, 3);
  EXPECT_EQ(r.info().dem_ranks, 2);
  EXPECT_EQ(pack_layout(r.info().layout), pack_layout(info.layout));
  EXPECT_EQ(r.state_steps().size(), 1500u);
  for (std::int64_t step : {0, 1, 1023, 1024, 1499}) {
    const auto s = r.states(step), es = states(step, 3);
    ASSERT_EQ(s.size(), es.size());
    EXPECT_EQ(std::memcmp(s.data(), es.data(), s.size() * sizeof(BodyState)), 0) << step;
    const auto l = r.loads(step), el = loads(step, static_cast<int>(step % 4));
    ASSERT_EQ(l.size(), el.size());
    if (!l.empty()) {
      EXPECT_EQ(std::memcmp(l.data(), el.data(), l.size() * sizeof(BodyLoad)), 0) << step;
    }
  }
  try {
    r.states(1500);
    FAIL() << "expected an error for a step that was not recorded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("recorded steps 0 to 1499"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

TEST(Recording, MissingOrForeignFileIsReported) {
  EXPECT_THROW(RecordingReader("/nonexistent/lbdem.h5"), std::runtime_error);
  const std::string path = temp_file("lbdem_not_a_recording");
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs("plain text", f);
    std::fclose(f);
  }
  try {
    RecordingReader r(path);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not an HDF5 file"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(Compare, ReportsFirstMismatchWithBothValues) {
  auto a = states(4, 3), b = a;
  EXPECT_FALSE(first_mismatch(4, a, b));
  b[1].q[2] = std::nextafter(b[1].q[2], 1.0);
  b[2].x[0] += 1;
  const auto m = first_mismatch(4, a, b);
  ASSERT_TRUE(m);
  EXPECT_EQ(*m, "step 4, body 1, q[2]: recorded 0, replayed 4.9406564584124654e-324");
  auto la = loads(9, 2), lb = la;
  lb[0].t[1] = -lb[0].t[1];
  EXPECT_NE(first_mismatch(9, la, lb)->find("step 9, body 0, t[1]: recorded "), std::string::npos);
  lb.pop_back();
  lb[0] = la[0];
  EXPECT_EQ(*first_mismatch(9, la, lb), "step 9, recorded 2 bodies, replayed 1");
}

TEST(Compare, SignedZeroAndNanAreComparedByBits) {
  auto a = loads(0, 1), b = a;
  a[0].f[0] = 0.0;
  b[0].f[0] = -0.0;
  EXPECT_TRUE(first_mismatch(0, a, b));
  a[0].f[0] = b[0].f[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(first_mismatch(0, a, b));
}

TEST(Reduce, SumsInSourceOrderWhateverTheArrival) {
  auto sent = states(2, 3);
  BodyLoad p;
  p.step = 2;
  p.id = 1;
  std::vector<std::vector<BodyLoad>> per(3);
  const double parts[3] = {1e16, 1.0, -1e16};
  for (int r = 0; r < 3; ++r) {
    p.f[0] = parts[r];
    per[static_cast<size_t>(r)].push_back(p);
  }
  const auto out = reduce_loads(sent, per, 2);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1].id, 1);
  EXPECT_EQ(out[1].f[0], (0.0 + 1e16 + 1.0) + -1e16);  // the rank order, not the exact sum
  EXPECT_EQ(out[0].f[0], 0.0);                         // no partials: zero load
  EXPECT_EQ(out[2].step, 2);
}

TEST(Reduce, RejectsForeignDuplicateAndStalePackets) {
  auto sent = states(2, 2);
  BodyLoad p;
  p.step = 2;
  p.id = 7;
  EXPECT_THROW(reduce_loads(sent, {{p}}, 2), std::runtime_error);
  p.id = 1;
  EXPECT_THROW(reduce_loads(sent, {{p, p}}, 2), std::runtime_error);
  EXPECT_NO_THROW(reduce_loads(sent, {{p}, {p}}, 2));
  p.step = 1;
  EXPECT_THROW(reduce_loads(sent, {{p}}, 2), std::runtime_error);
  p.step = 2;
  p.version = kProtocolVersion + 1;
  EXPECT_THROW(reduce_loads(sent, {{p}}, 2), std::runtime_error);
}

}  // namespace
}  // namespace lbdem

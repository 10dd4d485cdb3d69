#pragma once
// The loads of the bodies one DEM rank is home for: body b's home is rank b mod P, whatever
// rank owns or holds its spheres in LAMMPS. Loads set anywhere go to the home
// (dem_app/load_routing.hpp), and a rank asks the homes for the bodies of its own spheres,
// so each rank keeps N / P entries and a run touches only the bodies asked for.
//
// What a run applies to a body (dem_app/external_load.hpp): the force load + extra, the load
// torque, and in the run's first force evaluation (F_new - F_old) / 2 with F_old the load of
// the previous run. The previous load is kept lazily: an entry remembers the run its load was
// last set for, so an entry not set since then has F_old = F_new and nothing is visited.
#include <cstdint>
#include <vector>

#include "dem_app/external_load.hpp"

namespace lbdem {

// A load (kind 0: force and torque) or an extra force (kind 1) for one body, as set_load and
// set_extra_force record it until the next run.
struct LoadUpdate {
  std::int64_t id = 0;
  std::int64_t kind = 0;
  double f[3] = {0, 0, 0};
  double t[3] = {0, 0, 0};
};

class LoadTable {
 public:
  LoadTable() = default;
  LoadTable(std::int64_t bodies, int rank, int ranks);

  int home(std::int64_t id) const { return static_cast<int>(id % ranks_); }
  bool is_home(std::int64_t id) const { return home(id) == rank_; }
  std::int64_t bodies() const { return bodies_; }
  // Entries held here (about bodies / ranks).
  std::size_t size() const { return entries_.size(); }

  // A load or extra force for a body homed here, for the next run; the last one set wins.
  void update(const LoadUpdate& u);
  // Starts the next run: loads set from now on belong to the run after it.
  void begin_run() { ++run_; }
  // What the current run applies to a body homed here; kick: the run has a first-evaluation
  // correction (two substeps or more).
  AppliedLoad applied(std::int64_t id, bool kick) const;

 private:
  struct Entry {
    double load_f[3] = {0, 0, 0}, load_t[3] = {0, 0, 0};
    double previous_f[3] = {0, 0, 0}, previous_t[3] = {0, 0, 0};  // load of the run before
    double extra[3] = {0, 0, 0};
    std::int64_t run = 0;  // the run load_f and load_t were last set for
  };
  std::size_t index(std::int64_t id) const;  // checked

  std::int64_t bodies_ = 0;
  int rank_ = 0, ranks_ = 1;
  std::int64_t run_ = 0;        // runs begun
  std::vector<Entry> entries_;  // body rank + k ranks at k
};

}  // namespace lbdem

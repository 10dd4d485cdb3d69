#pragma once
// The lubrication correction inside the DEM steps (docs/lubrication.md). Called every step from
// the fix external callback (after the contacts, before the second half-kick), with the atoms'
// half-step velocities, so the stiff squeeze force is integrated with the contacts' time step.
//
// Pairs: clump spheres of different bodies whose surfaces are closer than h_c, found in a
// Verlet list over local and ghost atoms (cells of one interaction range, rebuilt only when
// LAMMPS has re-neighboured or an atom moved more than half the skin), and each local clump
// sphere against each plane wall. A local atom gets the force of every pair it is in; a pair
// with a ghost partner is evaluated on both ranks, each for its own atom, so no reverse
// communication is needed and the result does not depend on the decomposition.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem_app/lubrication/lubrication_law.hpp"

namespace lbdem {

struct LubricationWall {
  int axis = 2;
  bool lower = true;  // bodies lie above (lower) or below (upper) the plane
  double position = 0;
};

// Per-atom data of the LAMMPS arrays the correction reads (local atoms first, then ghosts).
struct AtomView {
  int nlocal = 0, nall = 0;
  const std::int64_t* tag = nullptr;  // converted to 64 bit by the caller if needed
  double** x = nullptr;
  double** v = nullptr;
  double** f = nullptr;       // only [0, nlocal) is written
  double** omega = nullptr;   // angular velocities (the wall's sliding part needs them)
  double** torque = nullptr;  // only [0, nlocal) is written
};

class Lubrication {
 public:
  Lubrication() = default;
  // atom_body, atom_radius: per atom tag - 1; radius 0 marks atoms that take no part (helper
  // spheres of one-sphere bodies). skin: the Verlet list's skin in m.
  Lubrication(const LubricationLaw& law, std::vector<std::int64_t> atom_body,
              std::vector<double> atom_radius, std::vector<LubricationWall> walls, double skin);

  bool enabled() const { return law_.viscosity > 0; }
  const LubricationLaw& law() const { return law_; }

  // Adds the correction to f and torque of the local atoms (normal squeeze film, and the
  // sliding and rolling parts of pairs and walls: lubrication_law.hpp).
  void apply(const AtomView& a);

  long builds() const { return builds_; }              // Verlet-list builds so far
  std::size_t pairs() const { return pairs_.size(); }  // candidate pairs in the current list

 private:
  bool list_is_stale(const AtomView& a) const;
  void build_list(const AtomView& a);

  LubricationLaw law_;
  std::vector<std::int64_t> atom_body_;
  std::vector<double> atom_radius_;
  std::vector<LubricationWall> walls_;
  double skin_ = 0, max_radius_ = 0;
  // The list: index pairs (i local; j local with j > i, or ghost), and what it was built on.
  std::vector<std::array<int, 2>> pairs_;
  std::vector<std::int64_t> built_tag_;
  std::vector<std::array<double, 3>> built_x_;
  int built_nlocal_ = -1;
  // Cells of the last build: the taking-part atoms sorted by cell, cell c's in
  // sorted_[start_[c], start_[c + 1]); scratch reused between builds.
  struct SortedAtom {
    std::array<double, 3> x;
    double radius;
    std::int64_t body;
    int index;  // in the LAMMPS arrays
  };
  std::vector<SortedAtom> sorted_;
  std::vector<std::size_t> start_, fill_, cell_;
  std::vector<char> has_local_;
  std::vector<std::int64_t> cell_body_;
  long builds_ = 0;
};

}  // namespace lbdem

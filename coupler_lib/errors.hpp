#pragma once
// The error classes of the whole project, below every layer so that any layer can throw them
// and the common main (coupler_lib/app/run_app.hpp) can tell them apart. Each message is
// complete and meant for the user as it is (file, key or rank, and what was expected).
#include <stdexcept>

namespace lbdem {

// Exit status of either program when a stability watch stopped the run (1 is any error).
inline constexpr int kExitUnstable = 3;

// Bad shape input (STL files, clump files, shape parameters).
class ShapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A bad scene (file, line, key and what was expected).
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An error that every rank of one program detects identically.
class SideError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An error that every rank of both programs detects identically (same message).
class JobError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lbdem

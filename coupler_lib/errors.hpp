#pragma once
// The error classes and exit statuses of the whole project, below every layer so that any
// layer can throw them and the common main (coupler_lib/app/run_app.hpp) can tell them apart. Each message is
// complete and meant for the user as it is (file, key or rank, and what was expected).
#include <stdexcept>

namespace lbdem {

// The exit statuses of both programs, in one place (docs/user-guide.md, "Running"):
//   0  done (or stopped on request with a checkpoint written)
//   1  any error: a bad scene, a failed partner, an I/O error (the message says which)
//   3  a stability watch stopped the run (diagnosis and last good state written)
//   4  fluid_app's validation: the error is above fluid.validation.tolerance
inline constexpr int kExitError = 1;
inline constexpr int kExitUnstable = 3;
inline constexpr int kExitValidationFailed = 4;

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

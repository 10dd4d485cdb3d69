#pragma once
// Errors in shape input (STL files, clump files, shape parameters). The message is complete
// and names the file and the problem.
#include <stdexcept>

namespace lbdem {

class ShapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lbdem

#pragma once
// Output files that a reader (ParaView, a plotting script) may open at any moment, and that a
// run dying during output must not leave half written: write to a temporary file, then
// rename it over the old one (atomic on POSIX file systems).
#include <string>

namespace lbdem {

// Writes `text` to `path` through `path`.tmp and a rename. Throws std::runtime_error naming
// the file when it cannot be written.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace lbdem

#pragma once
// Text series (CSV) that a restarted run continues: a checkpoint stores how many bytes each
// series held at its step; the restart cuts the file back to that length (dropping the rows
// the stopped run wrote after the checkpoint) and appends from there, so no row appears twice.
#include <string>

namespace lbdem {

// Cuts `path` to `bytes`. Throws std::runtime_error naming the file when it is missing or
// shorter than that (it was replaced or truncated since the checkpoint).
void cut_series_to(const std::string& path, long long bytes);

}  // namespace lbdem

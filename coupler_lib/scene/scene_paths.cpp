#include "coupler_lib/scene/scene_paths.hpp"

#include <unistd.h>

#include <filesystem>
#include <system_error>

namespace lbdem {

namespace fs = std::filesystem;

namespace {

bool writable_directory(const fs::path& p) {
  return ::access(p.c_str(), W_OK | X_OK) == 0;
}

}  // namespace

void check_plain_name(const Section& s, std::string_view key, const std::string& name) {
  bool plain = !name.empty() && name != "." && name != "..";
  for (const char c : name) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!letter && c != '-' && c != '_' && c != '.') plain = false;
  }
  if (!plain)
    s.fail(key, "'" + name +
                    "' is not a plain file name: output files are named after it, so it may "
                    "hold only letters, digits, '-', '_' and '.' (not '.' or '..' alone)");
}

void check_output_directory(const Section& s, std::string_view key, const std::string& dir) {
  std::error_code ec;
  const fs::path p(dir);
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec))
      s.fail(key, "'" + dir + "' exists and is not a directory; name a directory");
    if (!writable_directory(p)) s.fail(key, "the directory '" + dir + "' is not writable");
    return;
  }
  // Missing: the run creates it and the folders above it, from the nearest one that exists.
  fs::path up = p.parent_path();
  while (!up.empty() && !fs::exists(up, ec)) up = up.parent_path();
  if (up.empty()) up = ".";
  if (!fs::is_directory(up, ec))
    s.fail(key, "'" + dir + "' cannot be created: '" + up.string() + "' is not a directory");
  if (!writable_directory(up))
    s.fail(key, "'" + dir + "' cannot be created: '" + up.string() + "' is not writable");
}

void check_output_file(const Section& s, std::string_view key, const std::string& file) {
  std::error_code ec;
  const fs::path p(file);
  if (fs::is_directory(p, ec)) s.fail(key, "'" + file + "' is a directory; name a file");
  const fs::path folder = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  check_output_directory(s, key, folder.string());
  if (fs::exists(p, ec) && ::access(p.c_str(), W_OK) != 0)
    s.fail(key, "the file '" + file + "' exists and is not writable");
}

}  // namespace lbdem

#pragma once
// The names and paths a scene gives, checked when it is read, so that both programs' --check
// refuse what a run would fail on (or write somewhere unintended) and name file, line and key.
#include <string>
#include <string_view>

#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

// A name that becomes part of output file names: letters, digits, '-', '_' and '.', not empty,
// not "." or "..". Anything else (a '/', a space, "..") would put files outside the output
// directory or break the programs' file names.
void check_plain_name(const Section& s, std::string_view key, const std::string& name);

// A directory the run writes into (created if missing): it must be a directory if it exists,
// else the nearest folder above it that exists must be a directory; either must be writable.
void check_output_directory(const Section& s, std::string_view key, const std::string& dir);

// A file the run creates or replaces: not an existing folder, and its folder as above.
void check_output_file(const Section& s, std::string_view key, const std::string& file);

}  // namespace lbdem

#pragma once
// JSON text of scalar values, for the resolved scene (`--check --json`, coupler_lib/app/
// scene_json.hpp). Numbers are written in the shortest form that reads back to the same double,
// so a tool that reads the JSON gets exactly the numbers the programs use.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace lbdem {

std::string json_number(double v);  // non-finite values (never in a valid scene) become null
std::string json_string(std::string_view s);
std::string json_list(const std::vector<double>& v);

template <std::size_t N>
std::string json_list(const std::array<double, N>& v) {
  return json_list(std::vector<double>(v.begin(), v.end()));
}

}  // namespace lbdem

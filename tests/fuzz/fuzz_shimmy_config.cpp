// Fuzzes read_shimmy_config: a ParseError is the only expected failure; a configuration that
// is read must be valid and must read back unchanged from its own JSON (to_json).
#include <cstdio>
#include <fstream>

#include "config.hpp"
#include "contensou/friction/error.hpp"
#include "fuzz_input.hpp"

using namespace contensou;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = fuzz::write_input(data, size, "json");
  app::ShimmyConfig c;
  try {
    c = app::read_shimmy_config(path);
  } catch (const ParseError&) {
    return 0;
  }
  validate(c.gear);  // an InvalidArgument here escapes: the reader let a bad value through
  fuzz::require(!c.models.empty(), "no contact model");
  for (const app::MapSpec& m : c.maps)
    fuzz::require(m.x.points >= 1 && m.y.points >= 1, "map with fewer than 1 point");
  // The configuration written out reads back the same.
  const nlohmann::json j = app::to_json(c);
  const std::string again = path + ".again.json";
  std::ofstream(again) << j.dump();
  app::ShimmyConfig back;
  try {
    back = app::read_shimmy_config(again);
  } catch (const ParseError& e) {
    fuzz::finding(std::string("to_json output rejected: ") + e.what());
  }
  std::remove(again.c_str());
  fuzz::require(app::to_json(back) == j, "to_json output reads back different");
  return 0;
}

#include "fmu_model.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "contensou/friction/error.hpp"

namespace contensou::fmu {

namespace {
[[noreturn]] void no_such(unsigned vr, const char* type) {
  throw InvalidArgument("value reference", std::to_string(vr),
                        std::string("this FMU has no ") + type + " variable there");
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

void FmuModel::set_boolean(unsigned vr, bool) {
  no_such(vr, "Boolean");
}
bool FmuModel::get_boolean(unsigned vr) {
  no_such(vr, "Boolean");
}
void FmuModel::set_string(unsigned vr, const std::string&) {
  no_such(vr, "String");
}
std::string FmuModel::get_string(unsigned vr) {
  no_such(vr, "String");
}
double FmuModel::partial(unsigned unknown, unsigned known) {
  throw InvalidArgument("directional derivative",
                        std::to_string(unknown) + " by " + std::to_string(known),
                        "this FMU provides no directional derivatives");
}

std::string resource_path(const char* location) {
  if (!location || !*location)
    throw InvalidArgument("fmuResourceLocation", "empty",
                          "must be the URI of the FMU's resources folder (file:///...)");
  std::string s = location;
  if (s.rfind("file:", 0) == 0) {
    s.erase(0, 5);
    if (s.rfind("///", 0) == 0)
      s.erase(0, 2);
    else if (s.rfind("//localhost/", 0) == 0)
      s.erase(0, 11);
    else if (s.rfind("//", 0) == 0)
      throw InvalidArgument("fmuResourceLocation", location,
                            "names another host; only local files (file:///path) are read");
  } else if (s.find("://") != std::string::npos) {
    throw InvalidArgument("fmuResourceLocation", location, "only file: URIs are read");
  }
  std::string path;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && hex_digit(s[i + 1]) >= 0 && hex_digit(s[i + 2]) >= 0) {
      path += static_cast<char>(hex_digit(s[i + 1]) * 16 + hex_digit(s[i + 2]));
      i += 2;
    } else {
      path += s[i];
    }
  }
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  return path;
}

std::string read_resource_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error(path + ": cannot read the FMU's resource (" + std::strerror(errno) +
                             "): the archive is incomplete or was unpacked elsewhere");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw std::runtime_error(path + ": read error");
  return text.str();
}

std::string guid_of(const std::string& text) {
  auto fnv = [&](std::uint64_t h) {
    for (unsigned char c : text) h = (h ^ c) * 0x100000001b3ULL;
    return h;
  };
  const std::uint64_t a = fnv(0xcbf29ce484222325ULL), b = fnv(0x84222325cbf29ce4ULL);
  char buf[48];
  std::snprintf(buf, sizeof buf, "{%08x-%04x-%04x-%04x-%012llx}", unsigned(a >> 32),
                unsigned((a >> 16) & 0xffff), unsigned(a & 0xffff), unsigned(b >> 48),
                static_cast<unsigned long long>(b & 0xffffffffffffULL));
  return buf;
}

}  // namespace contensou::fmu

#include "zip_writer.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace contensou::fmu {

namespace {

// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320), as ZIP stores it.
std::uint32_t crc32(const std::string& data) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : data) c = table[(c ^ b) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void u16(std::string& out, std::uint32_t v) {
  out += static_cast<char>(v & 0xFFu);
  out += static_cast<char>((v >> 8) & 0xFFu);
}
void u32(std::string& out, std::uint32_t v) {
  u16(out, v & 0xFFFFu);
  u16(out, v >> 16);
}

std::uint32_t size32(std::size_t n, const std::string& what) {
  if (n >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error(what + ": too large for a ZIP archive without ZIP64");
  return static_cast<std::uint32_t>(n);
}

constexpr std::uint32_t kDosTime = 0;                            // 00:00:00
constexpr std::uint32_t kDosDate = (1u << 5) | 1u | (40u << 9);  // 1 January 2020

// The fields the local header and the central directory share.
void common(std::string& out, const ZipEntry& e, std::uint32_t crc) {
  u16(out, 20);  // version needed: 2.0
  u16(out, 0);   // flags
  u16(out, 0);   // stored
  u16(out, kDosTime);
  u16(out, kDosDate);
  u32(out, crc);
  u32(out, size32(e.data.size(), e.name));
  u32(out, size32(e.data.size(), e.name));
  u16(out, size32(e.name.size(), e.name) & 0xFFFFu);
  u16(out, 0);  // extra field length
}

}  // namespace

std::string zip_archive(const std::vector<ZipEntry>& entries) {
  std::string out, central;
  for (const ZipEntry& e : entries) {
    const std::uint32_t crc = crc32(e.data), offset = size32(out.size(), "the archive");
    u32(out, 0x04034b50u);
    common(out, e, crc);
    out += e.name;
    out += e.data;
    u32(central, 0x02014b50u);
    u16(central, (3u << 8) | 20u);  // made by: Unix, 2.0
    common(central, e, crc);
    u16(central, 0);               // comment length
    u16(central, 0);               // disk number
    u16(central, 0);               // internal attributes
    u32(central, 0100644u << 16);  // external: a regular file, rw-r--r--
    u32(central, offset);
    central += e.name;
  }
  const std::uint32_t directory = size32(out.size(), "the archive");
  out += central;
  u32(out, 0x06054b50u);
  u16(out, 0);
  u16(out, 0);
  u16(out, size32(entries.size(), "entries") & 0xFFFFu);
  u16(out, size32(entries.size(), "entries") & 0xFFFFu);
  u32(out, size32(central.size(), "the directory"));
  u32(out, directory);
  u16(out, 0);
  size32(out.size(), "the archive");
  return out;
}

}  // namespace contensou::fmu

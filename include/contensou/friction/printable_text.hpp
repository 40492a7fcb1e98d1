/// \file
/// Text that every structured output carries as written: names a user gives (an FMU's model
/// name, a profile's name) go into XML attributes, JSON strings, CSV cells and plot titles, and a
/// control character or a broken UTF-8 byte makes the file one its reader refuses. One check,
/// used wherever such a name is taken.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

#include "contensou/friction/error.hpp"

namespace contensou {

/// Where `text` stops being text every structured output carries as written (XML 1.0
/// attributes, JSON strings, CSV cells, gnuplot titles): the 0-based byte of the first control
/// character (U+0000 to U+001F but tab and newline, and U+007F) or of the first byte that is not
/// well-formed UTF-8, with a description ("the control character U+0001"); npos if none.
inline std::size_t first_unprintable(const std::string& text, std::string* what = nullptr) {
  const auto at = [&](std::size_t i, const std::string& w) {
    if (what) *what = w;
    return i;
  };
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    if ((b < 0x20 && b != '\t' && b != '\n') || b == 0x7f) {
      char code[16];
      std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(b));
      return at(i, std::string("the control character ") + code);
    }
    // UTF-8: a lead byte 0xxxxxxx, 110xxxxx, 1110xxxx or 11110xxx, then 10xxxxxx bytes.
    const std::size_t n = b < 0x80           ? 1
                          : (b >> 5) == 0x6  ? 2
                          : (b >> 4) == 0xe  ? 3
                          : (b >> 3) == 0x1e ? 4
                                             : 0;
    bool ok = n > 0 && i + n <= text.size() && !(n == 2 && b < 0xc2);
    for (std::size_t k = 1; ok && k < n; ++k)
      ok = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
    if (!ok) return at(i, "a byte that is not UTF-8");
    i += n;
  }
  return std::string::npos;
}

/// Throws InvalidArgument naming `name` unless `text` is printable UTF-8 (first_unprintable):
/// a name written into XML, JSON, CSV or a plot must not be refused by the tool that reads it.
inline void require_printable(const char* name, const std::string& text) {
  std::string what;
  const std::size_t i = first_unprintable(text, &what);
  if (i == std::string::npos) return;
  std::string shown;  // the text with the bad bytes as \xNN
  for (unsigned char c : text) {
    if (c >= 0x20 && c < 0x7f) {
      shown += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned>(c));
      shown += hex;
    }
  }
  throw InvalidArgument(name, "\"" + shown + "\"",
                        "byte " + std::to_string(i + 1) + " is " + what +
                            ", which XML and the other outputs cannot carry: use printable text");
}

}  // namespace contensou

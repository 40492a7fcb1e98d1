/// \file
/// How messages name an option of the identification: as the app's command line writes it
/// (--normal-load, --columns vx=Speed) or as Python's keyword (normal_load, columns={'vx':
/// 'Speed'}), so that an error points at what the user typed.
#pragma once

#include <string>
#include <string_view>

namespace contensou {

/// The front end whose spelling of the options messages use.
enum class KeyStyle {
  command_line,  ///< contensou-identify's options: "--normal-load", "--columns vx=Speed"
  python         ///< Python's keywords: "normal_load", "columns={'vx': 'Speed'}"
};

/// A key ("normal_load") as the style writes it: "--normal-load" (underscores turned into
/// hyphens) or "normal_load" (unchanged).
std::string key_name(std::string_view key, KeyStyle style);

/// The rename of `quantity` to the header cell `column`: "--columns vx=Speed" (a column with
/// characters other than letters, digits, '_', '-' and '.' in shell single quotes) or
/// "columns={'vx': 'Speed'}".
std::string rename_option(const std::string& quantity, const std::string& column, KeyStyle style);

}  // namespace contensou

// The FMU binaries built with the project, embedded in the exporter (embedded_binaries.cpp,
// assembled with .incbin from the build's own shared objects), so that contensou-fmu and the
// library need no file beside them to write an archive.
#pragma once

#include <string_view>

namespace contensou::fmu {

std::string_view law_fmu_binary();   // contensou_law.so
std::string_view gear_fmu_binary();  // contensou_gear.so ("" when the gear module is not built)

}  // namespace contensou::fmu

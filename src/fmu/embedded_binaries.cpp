#include "embedded_binaries.hpp"

// CONTENSOU_LAW_FMU_BINARY and CONTENSOU_GEAR_FMU_BINARY: paths of the built shared objects
// (src/fmu/CMakeLists.txt), whose bytes the assembler includes in .rodata.
#define CONTENSOU_EMBED(symbol, path)                                                    \
  __asm__(".pushsection .rodata\n.balign 64\n.globl " #symbol "_begin\n.hidden " #symbol \
          "_begin\n" #symbol "_begin:\n.incbin \"" path "\"\n.globl " #symbol            \
          "_end\n.hidden " #symbol "_end\n" #symbol "_end:\n.byte 0\n.popsection\n")

CONTENSOU_EMBED(contensou_law_fmu, CONTENSOU_LAW_FMU_BINARY);
#ifdef CONTENSOU_GEAR_FMU_BINARY
CONTENSOU_EMBED(contensou_gear_fmu, CONTENSOU_GEAR_FMU_BINARY);
#endif

namespace contensou::fmu {

namespace {
std::string_view between(const char* begin, const char* end) {
  return {begin, static_cast<std::size_t>(end - begin)};
}
}  // namespace

std::string_view law_fmu_binary() {
  extern const char contensou_law_fmu_begin[] __asm__("contensou_law_fmu_begin");
  extern const char contensou_law_fmu_end[] __asm__("contensou_law_fmu_end");
  return between(contensou_law_fmu_begin, contensou_law_fmu_end);
}

std::string_view gear_fmu_binary() {
#ifdef CONTENSOU_GEAR_FMU_BINARY
  extern const char contensou_gear_fmu_begin[] __asm__("contensou_gear_fmu_begin");
  extern const char contensou_gear_fmu_end[] __asm__("contensou_gear_fmu_end");
  return between(contensou_gear_fmu_begin, contensou_gear_fmu_end);
#else
  return {};
#endif
}

}  // namespace contensou::fmu

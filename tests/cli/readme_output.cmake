# Runs the README's C++ quick start (PROGRAM) and compares what it prints with the ```text block
# that follows the ```cpp block in README.md, line by line, leaving out parenthesised parts
# (error estimates and bounds, which may differ in the last digit between machines).
# Usage: cmake -DPROGRAM=... -DREADME=.../README.md -P readme_output.cmake
execute_process(COMMAND ${PROGRAM} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the C++ quick start exited with ${rc}:\n${out}${err}")
endif()
file(READ ${README} readme)
string(REGEX MATCH "```cpp\n[^`]*int main[^`]*```[^`]*```text\n([^`]*)```" block "${readme}")
if(NOT CMAKE_MATCH_1)
  message(FATAL_ERROR "README.md: no ```text block after the C++ quick start (its printed output)")
endif()
set(expected "${CMAKE_MATCH_1}")
foreach(v out expected)
  string(REGEX REPLACE "\\([^)]*\\)" "" ${v} "${${v}}")
  string(REGEX REPLACE "[ \t]+\n" "\n" ${v} "${${v}}")
  string(STRIP "${${v}}" ${v})
endforeach()
if(NOT out STREQUAL expected)
  message(FATAL_ERROR "the C++ quick start prints\n${out}\nbut README.md shows\n${expected}")
endif()
message(STATUS "the C++ quick start prints what README.md shows")

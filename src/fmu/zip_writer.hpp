// A ZIP archive of stored (uncompressed) entries, as the FMI standard's archive format allows
// (FMI 2.0.4, section 2.3: a zip file; stored and deflated entries are read by every importer).
// Entries carry a fixed time stamp, so that one export gives the same bytes every time.
#pragma once

#include <string>
#include <vector>

namespace contensou::fmu {

struct ZipEntry {
  std::string name;  // path inside the archive, '/'-separated
  std::string data;
};

// The archive's bytes. Throws std::length_error past the 32-bit sizes of the plain ZIP format.
std::string zip_archive(const std::vector<ZipEntry>& entries);

}  // namespace contensou::fmu

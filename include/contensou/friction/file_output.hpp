/// \file
/// Files written whole or not at all: every file the library and its apps write goes through
/// write_file_atomically, so that a kill, a full disk or two runs at once never leave a partial
/// or mixed file where the previous one was.
#pragma once

#include <string>
#include <string_view>

namespace contensou {

/// Writes `text` to `path`:
///  - a regular file (or a new one, or a symlink to either): into a fresh temporary file of a
///    unique name (mkstemp) in the same folder, fsync, then renamed over `path` (a symlink is
///    followed and its target replaced, the link kept). Readers see the old file or the new one,
///    never a mix; two writers each leave a whole file.
///  - a character device or a FIFO (/dev/null, a pipe): written through; a FIFO without a
///    reader is refused rather than waited on. /dev/stdout, /dev/stderr, /dev/fd/N and
///    /proc/self/fd/N are written to that descriptor of this process, whatever it is (a pipe, a
///    terminal, a file the shell opened), after standard output is flushed.
///  - anything else (a folder, a socket): refused.
/// Throws std::runtime_error naming the path and the system's reason (no space left, file too
/// large, permission denied) on any failure; the previous file is then left as it was.
void write_file_atomically(const std::string& path, std::string_view text);

/// The temporary file a write to `path` goes through: ".NAME.contensou-tmp-TAG" in path's folder,
/// NAME cut (at a UTF-8 character) so that the name stays within 255 bytes.
std::string temporary_path_for(const std::string& path, const std::string& tag);

/// True for a file name (no folder) that temporary_path_for makes: a killed run's leftover.
bool is_temporary_file_name(const std::string& name);

}  // namespace contensou

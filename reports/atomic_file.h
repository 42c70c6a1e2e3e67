// Writing output files so a reader never sees half of one: write a temporary file beside the
// target, then rename it over the target (rename is atomic within one file system, POSIX).
#pragma once

#include <string>

namespace skinsim::reports {

// Writes `content` to `path` atomically. Throws ReportError naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& content);

// A temporary path beside `path` (same directory, so the final rename stays on one file
// system). The name keeps `path`'s extension, for writers that choose a format by extension.
std::string temporary_path_beside(const std::string& path);

// Renames `from` over `to`; throws ReportError naming both on failure.
void replace_file(const std::string& from, const std::string& to);

}  // namespace skinsim::reports

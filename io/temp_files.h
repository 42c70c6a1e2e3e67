// Temporary files and directories beside the outputs they become, under one recognisable
// name pattern, so that ones left behind by a killed process can be found and removed.
#pragma once

#include <filesystem>
#include <string>

namespace skinsim::io {

// This machine's host name (gethostname), or "unknown".
std::string host_name();

// ".NAME.skinsim-tmp.HOST.PID.N" in `target`'s directory: hidden, unique within this process
// (N counts up), and naming the host and process that own it.
std::filesystem::path temporary_path_beside(const std::filesystem::path& target);

// Whether `name` (a file name, no directory) follows the pattern above.
bool is_temporary_name(const std::string& name);

// Removes temporaries in `dir` (not recursively) whose owner is gone: made on this host by a
// process that no longer runs, or made on another host more than a day ago (a process cannot
// be checked there). A live process's temporaries are kept. Returns how many were removed;
// errors (an unreadable directory, a file removed concurrently) are ignored, as this is
// housekeeping and the write that follows reports real problems.
int remove_stale_temporaries(const std::filesystem::path& dir);
// The same in `dir` and every directory below it (a sweep's directory tree).
int remove_stale_temporaries_in_tree(const std::filesystem::path& dir);

}  // namespace skinsim::io

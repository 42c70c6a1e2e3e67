// Runs a helper program (Blender, skinsim-exr) and waits for it: `skinsim truth` keeps
// programs with heavy libraries out of skinsim's own process.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace skinsim::driver {

// Runs argv[0] (searched in PATH when it has no '/') with its standard output and error
// appended to `log`, and returns its exit status (128 + the signal when one ended it).
// Throws UserError naming the program when it cannot be started (e.g. not installed).
int run_program(const std::vector<std::string>& argv, const std::filesystem::path& log);

// The path of a helper program: $`env_var` when set, else `name` beside the running
// executable when there, else `name` (to be searched in PATH).
std::string helper_program(const char* env_var, const std::string& name);

// Whether `program` can be run: a path to an executable file, or a name found in PATH.
bool program_exists(const std::string& program);

}  // namespace skinsim::driver

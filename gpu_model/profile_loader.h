// Loading and validating device profiles (TOML, see data/devices/ipad4.toml for the format).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gpu_model/device_profile.h"

namespace skinsim::gpu_model {

// A bare name such as "ipad4" resolves to <data_dir>/devices/ipad4.toml; anything containing
// a '/' or ending in ".toml" is taken as a path. Throws ProfileError naming the file and the
// dotted field on any problem (missing or unknown field, wrong type, out-of-range value).
DeviceProfile load_device_profile(const std::string& name_or_path, const std::string& data_dir);

// Parses profile text; `file_name` is used in error messages and as DeviceProfile::source_path,
// and its stem becomes DeviceProfile::name.
DeviceProfile parse_device_profile(std::string_view toml_text, const std::string& file_name);

// Names (file stems) of the profiles shipped in <data_dir>/devices, sorted.
std::vector<std::string> list_devices(const std::string& data_dir);

// Every profile in <data_dir>/devices, loaded one by one so that a broken file does not hide
// the others.
struct DeviceCatalog {
  std::vector<DeviceProfile> profiles;  // those that loaded, sorted by name
  std::vector<std::string> problems;    // one per file that did not: the loader's message
};

// Throws ProfileError only when the directory itself is missing.
DeviceCatalog load_device_catalog(const std::string& data_dir);

}  // namespace skinsim::gpu_model

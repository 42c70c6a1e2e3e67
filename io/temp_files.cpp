#include "io/temp_files.h"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <optional>
#include <string_view>
#include <vector>

namespace skinsim::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMarker = ".skinsim-tmp.";
// Another host's processes cannot be checked: its temporaries count as stale after a day.
constexpr auto kForeignHostMaxAge = std::chrono::hours(24);

// The host name with dots replaced, so the fields of a temporary's name stay dot-separated.
std::string host_field() {
  std::string host = host_name();
  for (char& c : host) {
    if (c == '.' || c == '/') c = '_';
  }
  return host;
}

struct TemporaryOwner {
  std::string host;
  long long pid = 0;
};

bool all_digits(std::string_view s, std::size_t max_length) {
  return !s.empty() && s.size() <= max_length &&
         s.find_first_not_of("0123456789") == std::string_view::npos;
}

// Parses ".NAME.skinsim-tmp.HOST.PID.N", optionally followed by an extension a writer
// appends (".N.png"). Plain string handling rather than std::regex: GCC 12 reports false
// -Wmaybe-uninitialized warnings inside <regex> under the sanitizers.
std::optional<TemporaryOwner> temporary_owner(std::string_view name) {
  if (name.size() < 2 || name[0] != '.') return std::nullopt;
  const std::size_t marker = name.find(kMarker, 1);
  if (marker == std::string_view::npos) return std::nullopt;
  std::string_view rest = name.substr(marker + std::string_view(kMarker).size());
  std::string_view fields[3];
  for (std::string_view& field : fields) {
    const std::size_t dot = rest.find('.');
    field = rest.substr(0, dot);
    rest = dot == std::string_view::npos ? std::string_view() : rest.substr(dot + 1);
    if (dot == std::string_view::npos && &field != &fields[2]) return std::nullopt;
  }
  if (fields[0].empty() || !all_digits(fields[1], 10) || !all_digits(fields[2], 20)) {
    return std::nullopt;
  }
  return TemporaryOwner{std::string(fields[0]), std::stoll(std::string(fields[1]))};
}

bool process_is_gone(long long pid) {
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace

std::string host_name() {
  char buffer[256] = {};
  if (::gethostname(buffer, sizeof(buffer) - 1) != 0 || buffer[0] == '\0') return "unknown";
  return buffer;
}

fs::path temporary_path_beside(const fs::path& target) {
  static std::atomic<unsigned long> counter{0};
  const std::string name = fmt::format(".{}{}{}.{}.{}", target.filename().string(), kMarker,
                                       host_field(), ::getpid(), counter++);
  return target.parent_path() / name;
}

bool is_temporary_name(const std::string& name) {
  return temporary_owner(name).has_value();
}

int remove_stale_temporaries(const fs::path& dir) {
  std::error_code ec;
  fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec);
  if (ec) return 0;
  const std::string host = host_field();
  int removed = 0;
  for (const fs::directory_entry& entry : it) {
    const std::string name = entry.path().filename().string();
    const std::optional<TemporaryOwner> owner = temporary_owner(name);
    if (!owner) continue;
    bool stale = false;
    if (owner->host == host) {
      stale = process_is_gone(owner->pid);
    } else {
      const auto written = fs::last_write_time(entry.path(), ec);
      stale = !ec && fs::file_time_type::clock::now() - written > kForeignHostMaxAge;
    }
    if (stale && fs::remove_all(entry.path(), ec) > 0 && !ec) ++removed;
  }
  return removed;
}

int remove_stale_temporaries_in_tree(const fs::path& dir) {
  int removed = remove_stale_temporaries(dir);
  std::error_code ec;
  std::vector<fs::path> subdirs;  // collected first: removing while iterating is unspecified
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_directory(ec) && !it->is_symlink(ec)) subdirs.push_back(it->path());
  }
  for (const fs::path& sub : subdirs) removed += remove_stale_temporaries(sub);
  return removed;
}

}  // namespace skinsim::io

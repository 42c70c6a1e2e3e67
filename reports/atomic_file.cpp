#include "reports/atomic_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <system_error>

#include "reports/report_error.h"

namespace skinsim::reports {

namespace fs = std::filesystem;

std::string temporary_path_beside(const std::string& path) {
  const fs::path target(path);
  fs::path tmp = target.parent_path() / (target.stem().string() + ".tmp" +
                                         std::to_string(::getpid()) + target.extension().string());
  return tmp.string();
}

void replace_file(const std::string& from, const std::string& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) {
    fs::remove(from, ec);
    throw ReportError("cannot move " + from + " to " + to + ": " + ec.message());
  }
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_path_beside(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw ReportError("cannot write " + path + ": cannot create " + tmp);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw ReportError("cannot write " + path + ": write to " + tmp + " failed");
    }
  }
  replace_file(tmp, path);
}

}  // namespace skinsim::reports

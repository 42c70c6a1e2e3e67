// The sweep's progress line on stderr: configurations done/total, elapsed time and the
// estimated time remaining. On a terminal one line is redrawn in place (\r); otherwise (a log
// file, CI) one line is printed per finished configuration.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace skinsim::driver {

class SweepProgress {
 public:
  // `total` configurations, `already_done` of them finished by an earlier run (resumed).
  // `out` null: silent.
  SweepProgress(int total, int already_done, std::FILE* out);

  // Call when the configurations start (after the scenes and references are ready): the
  // remaining-time estimate counts from here.
  void start_configs();
  // Thread-safe: one configuration finished after `seconds` of work.
  void finished(const std::string& id, double seconds);
  // Prints a note (e.g. "interrupted") on its own line without breaking the bar.
  void note(const std::string& text);
  // Ends the bar's line.
  void close();

  // "1m05s", "12.3s": durations as the bar prints them.
  static std::string format_duration(double seconds);

 private:
  std::string line(const std::string& last_id) const;

  std::mutex mutex_;
  std::FILE* out_;
  bool tty_;
  int total_;
  int done_;
  int done_here_ = 0;  // finished by this run: the ETA's rate counts only these
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point configs_start_;
};

}  // namespace skinsim::driver

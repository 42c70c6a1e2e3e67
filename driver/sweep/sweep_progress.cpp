#include "driver/sweep/sweep_progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>

namespace skinsim::driver {

SweepProgress::SweepProgress(int total, int already_done, std::FILE* out)
    : out_(out),
      tty_(out != nullptr && isatty(fileno(out)) != 0),
      total_(total),
      done_(already_done),
      start_(std::chrono::steady_clock::now()),
      configs_start_(start_) {
  if (out_ && already_done > 0) {
    fmt::print(out_, "resuming: {} of {} configurations already finished\n", already_done, total);
  }
}

std::string SweepProgress::format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "?";
  if (seconds < 60.0) return fmt::format("{:.1f}s", seconds);
  const long s = std::lround(seconds);
  if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

void SweepProgress::start_configs() {
  const std::lock_guard lock(mutex_);
  configs_start_ = std::chrono::steady_clock::now();
}

std::string SweepProgress::line(const std::string& last_id) const {
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // Configurations run in parallel, so the wall time per finished one is the fair rate.
  const double configs_elapsed = std::chrono::duration<double>(now - configs_start_).count();
  const int remaining = total_ - done_;
  const std::string eta =
      done_here_ > 0 ? format_duration(configs_elapsed / done_here_ * remaining) : std::string("?");
  constexpr int kWidth = 24;
  const int filled = total_ > 0 ? done_ * kWidth / total_ : kWidth;
  return fmt::format("[{}{}] {}/{} configs, elapsed {}, remaining ~{}  {}",
                     std::string(static_cast<std::size_t>(filled), '#'),
                     std::string(static_cast<std::size_t>(kWidth - filled), '.'), done_, total_,
                     format_duration(elapsed), eta, last_id);
}

void SweepProgress::finished(const std::string& id, double seconds) {
  const std::lock_guard lock(mutex_);
  ++done_;
  ++done_here_;
  if (!out_) return;
  if (tty_) {
    fmt::print(out_, "\r\033[K{}", line(id));
  } else {
    fmt::print(out_, "{} ({})\n", line(id), format_duration(seconds));
  }
  std::fflush(out_);
}

void SweepProgress::note(const std::string& text) {
  const std::lock_guard lock(mutex_);
  if (!out_) return;
  fmt::print(out_, "{}{}\n", tty_ && done_here_ > 0 ? "\n" : "", text);
  std::fflush(out_);
}

void SweepProgress::close() {
  const std::lock_guard lock(mutex_);
  if (out_ && tty_ && done_here_ > 0) fmt::print(out_, "\n");
}

}  // namespace skinsim::driver

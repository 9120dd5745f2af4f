#pragma once
/// A one-line progress bar on stderr, shown only when stderr is a terminal (isatty), so logs
/// and batch jobs stay clean. Thread-safe.

#include <mutex>
#include <string>

namespace cogmap::experiments {

class ProgressBar {
 public:
  /// `enabled` false makes every call a no-op; use ProgressBar::stderr_is_terminal().
  explicit ProgressBar(bool enabled) : enabled_(enabled) {}
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// True when stderr is a terminal.
  static bool stderr_is_terminal();

  /// Redraws the bar at `fraction` (clamped to [0, 1]) with `label` after it.
  void update(double fraction, const std::string& label);
  /// Clears the line (also done by the destructor).
  void finish();

 private:
  bool enabled_;
  bool drawn_ = false;
  std::mutex mutex_;
};

}  // namespace cogmap::experiments

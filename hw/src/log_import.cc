// Log format detection and the cogmap export of an import. The importers themselves are
// carmen_import.cc and player_import.cc.
#include "cogmap/hw/log_import.h"

#include <algorithm>
#include <string_view>

#include "import_common.h"
#include "log_checks.h"

namespace cogmap::hw {
namespace {

bool all_digits(const std::string& t) {
  return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool is_name(const std::string& t) {
  return !t.empty() && t[0] >= 'a' && t[0] <= 'z' && std::all_of(t.begin(), t.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

// writelog's "time host robot interface index type subtype": any interface.
bool is_player_line(const std::vector<std::string>& t) {
  if (t.size() < 7 || t[0].find_first_not_of("0123456789.") != std::string::npos) return false;
  return all_digits(t[1]) && all_digits(t[2]) && is_name(t[3]) && all_digits(t[4]) &&
         all_digits(t[5]) && all_digits(t[6]);
}

}  // namespace

LogFormat detect_log_format(const std::filesystem::path& path) {
  std::ifstream in = detail::open_log(path);
  std::string text;
  std::size_t line_no = 0;
  while (line_no < 1000 && detail::read_bounded_line(in, text, path, line_no + 1, LogLimits{})) {
    ++line_no;
    if (text.rfind("## Player", 0) == 0) return LogFormat::kPlayer;
    if (text.rfind("# CARMEN Logfile", 0) == 0) return LogFormat::kCarmen;  // the logger's header
    const auto t = detail::tokens_of(text);
    if (t.empty() || t[0][0] == '#') continue;
    if (t[0] == kLogMagic) return LogFormat::kCogmap;
    if (detail::is_carmen_message(t[0])) return LogFormat::kCarmen;
    // A writelog line of any interface; or Player 1.x's `position` (the importer says why it
    // does not read it).
    if (is_player_line(t) || (t.size() >= 6 && t[3] == "position")) return LogFormat::kPlayer;
    throw LogError(path.string() + ":" + std::to_string(line_no) +
                   ": expected a cogmap, CARMEN or Player log line, got '" +
                   detail::printable(text, 60) + "'");
  }
  throw LogError(path.string() + ": empty log (no frame lines)");
}

void write_cogmap_log(const std::filesystem::path& path, const ImportedLog& log) {
  LogWriter writer(path, log.geometry);
  for (const mapper::SensorFrame& f : log.frames) writer.write_line(format_frame_line(f));
}

}  // namespace cogmap::hw

#pragma once
/// Subcommands of the `cogmap` executable register themselves here, one file per command, so
/// modules add commands without editing a shared list.

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace cogmap::cli {

/// Exit codes of every subcommand (docs/formats.md): 0 ok, 1 failed run, 2 bad usage or input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;

/// Adds one subcommand to `app`; the callback it installs must set `exit_code`.
using CommandAdder = std::function<void(CLI::App& app, int& exit_code)>;

struct CommandEntry {
  std::string name;
  CommandAdder add;
};

std::vector<CommandEntry>& command_registry();

/// Define one `static const CommandRegistrar` per command file.
struct CommandRegistrar {
  CommandRegistrar(std::string name, CommandAdder add);
};

}  // namespace cogmap::cli

// The cogmap command line: every subcommand lives in its own *_command.cc and registers itself.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <exception>
#include <iostream>

#include "command_registry.h"

namespace cogmap::cli {

std::vector<CommandEntry>& command_registry() {
  static std::vector<CommandEntry> entries;
  return entries;
}

CommandRegistrar::CommandRegistrar(std::string name, CommandAdder add) {
  command_registry().push_back({std::move(name), std::move(add)});
}

}  // namespace cogmap::cli

int main(int argc, char** argv) {
  using namespace cogmap::cli;
  CLI::App app{"cogmap: sonar cognitive mapping testbed (MHIMM grids, ASRs, EM localisation)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "cogmap 0.1.0");
  int exit_code = kExitOk;
  auto entries = command_registry();
  std::sort(entries.begin(), entries.end(),
            [](const CommandEntry& a, const CommandEntry& b) { return a.name < b.name; });
  for (const CommandEntry& entry : entries) entry.add(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? kExitOk : kExitBadInput;
  }
  return exit_code;
}

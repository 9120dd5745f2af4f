// The cogmap command line: every subcommand lives in its own *_command.cc and registers itself.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>

#include "cogmap/sim/yaml_strict.h"
#include "command_registry.h"

namespace cogmap::cli {

std::vector<CommandEntry>& command_registry() {
  static std::vector<CommandEntry> entries;
  return entries;
}

CommandRegistrar::CommandRegistrar(std::string name, CommandAdder add) {
  command_registry().push_back({std::move(name), std::move(add)});
}

namespace {

// What a last-resort handler prints: the exception's message when there is one.
std::string describe_current_exception() {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    return "out of memory (std::bad_alloc)";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown exception";
  }
}

// An exception escaping a thread (or a noexcept function) ends here instead of in abort():
// one line on stderr and exit 1, never a core dump with SIGABRT.
[[noreturn]] void on_terminate() {
  const std::string what =
      std::current_exception() ? describe_current_exception() : "std::terminate called";
  std::cerr << "cogmap: internal error: " << what << " (please report this)\n";
  std::_Exit(kExitFailed);
}

// What the command printed must reach its destination: `cogmap sonar-stats >full-disk/x.txt`
// exited 0 with an empty or cut file (stdout is buffered, so the error shows only on the last
// flush, after the command returned). Returns false, with the reason on stderr, when it did not.
bool stdout_written() {
  errno = 0;
  std::cout.flush();  // with sync_with_stdio, fflush(stdout): errno says why it failed
  const bool failed = std::cout.fail() || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if (!failed) return true;
  const int saved = errno;
  std::cerr << "cogmap: standard output: write failed"
            << (saved != 0 ? std::string(": ") + std::strerror(saved) : std::string())
            << " (what was printed is incomplete)\n";
  return false;
}

}  // namespace

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
  std::set_terminate(on_terminate);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    if (rc == 0) return stdout_written() ? kExitOk : kExitFailed;  // --help, --version
    return kExitBadInput;
  } catch (const cogmap::yaml::ConfigError& e) {
    std::cerr << "cogmap: " << e.what() << "\n";  // bad input a subcommand did not expect
    return kExitBadInput;
  } catch (...) {
    // The last resort: every subcommand reports its own errors; anything that still escapes
    // is a bug, but it must end in a message and exit 1, not a crash.
    std::cerr << "cogmap: internal error: " << describe_current_exception()
              << " (please report this)\n";
    return kExitFailed;
  }
  if (!stdout_written() && exit_code == kExitOk) return kExitFailed;
  return exit_code;
}

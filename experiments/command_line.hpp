// Command-line parsing shared by the tools: --help prints and exits 0; a usage
// error prints one line naming the tool and exits 2 (docs/architecture.md,
// "Command line").
#pragma once

#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>

namespace corrmp {

// The exit code to return at once, or nothing when the tool should go on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << app.get_name() << ": " << e.what() << " (see --help)\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace corrmp

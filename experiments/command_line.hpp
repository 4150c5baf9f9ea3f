// Command-line parsing shared by the tools: --help prints and exits 0; a usage
// error prints one line naming the tool and exits 2 (docs/architecture.md,
// "Command line").
#pragma once

#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>
#include <string>

namespace corrmp {

// A number above zero; unlike CLI::PositiveNumber, the message does not print the largest
// double ("Value 0 not in range 0 to 1797693134862315...").
inline const CLI::Validator& positive_number() {
  static const CLI::Validator check(
      [](std::string& text) -> std::string {
        double value = 0.0;
        try {
          size_t used = 0;
          value = std::stod(text, &used);
          if (used != text.size()) return "'" + text + "' is not a number";
        } catch (const std::exception&) {
          return "'" + text + "' is not a number";
        }
        return value > 0.0 ? std::string() : "must be > 0, got " + text;
      },
      "> 0", "positive");
  return check;
}

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

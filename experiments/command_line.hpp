// Command-line parsing shared by the tools: --help prints and exits 0; a usage
// error (a value that is not a number for a numeric option too) prints one line
// naming the tool and exits 2 (docs/architecture.md, "Command line").
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>
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

// Checks `text` as a value of an option of CLI11 type `type` ("INT", "UINT" or "FLOAT"): returns
// what is wrong, or "" after writing integers in plain decimal (CLI11 would read "010" as octal).
inline std::string check_number(const std::string& type, std::string& text) {
  if (type == "FLOAT") {
    try {
      size_t used = 0;
      const double value = std::stod(text, &used);
      if (used == text.size() && std::isfinite(value)) return "";
    } catch (const std::out_of_range&) {
      return "'" + text + "' is out of range";
    } catch (const std::exception&) {
    }
    return "expected a number, got '" + text + "'";
  }
  const bool negative = !text.empty() && text[0] == '-';
  const size_t sign = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  const bool digits =
      text.size() > sign && std::all_of(text.begin() + sign, text.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
      });
  if (type == "UINT" && (!digits || negative)) {
    return "expected a non-negative integer, got '" + text + "'";
  }
  if (!digits) return "expected an integer, got '" + text + "'";
  const size_t first = std::min(text.find_first_not_of('0', sign), text.size() - 1);
  text = (negative ? "-" : "") + text.substr(first);
  try {  // CLI11 would clamp or misreport a value past the type's range
    if (type == "UINT")
      (void)std::stoull(text);
    else
      (void)std::stoll(text);
  } catch (const std::out_of_range&) {
    return "'" + text + "' is out of range";
  }
  return "";
}

// Makes check_number the first check of every integer and floating-point option of `app` and of
// its subcommands, so that a value that is not a number is named as such
// ("--threads: expected an integer, got 'abc'"): CLI::Range would say "Value abc not in range 1
// to 1024", a failed conversion "Could not convert: --seed = abc", and "--seed -1" would wrap.
inline void check_numeric_options(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string full_type = option->get_type_name();
    const std::string type = full_type.substr(0, full_type.find(':'));
    if (type != "INT" && type != "UINT" && type != "FLOAT") continue;
    option->transform(
        CLI::Validator([type](std::string& text) { return check_number(type, text); }, ""));
  }
  for (CLI::App* subcommand : app.get_subcommands([](CLI::App*) { return true; })) {
    check_numeric_options(*subcommand);
  }
}

// The exit code to return at once, or nothing when the tool should go on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  check_numeric_options(app);
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

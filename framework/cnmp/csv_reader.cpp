// Reader for per-demonstration CSV files: a header row naming the columns, then one row of numbers
// per time step. Each file becomes one [T, D] trajectory, like one slice of the [N, T, D] .npy
// arrays of the public CNMP code of Seker et al. (RSS 2019).
#include "cnmp/csv_reader.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/file_read.hpp"

namespace corrmp {
namespace {

struct CsvTrajectory {
  RawTrajectory trajectory;
  int header_line = 0;
};

std::string trim(const std::string& text) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t'; };
  std::size_t begin = 0, end = text.size();
  while (begin < end && is_space(text[begin])) ++begin;
  while (end > begin && is_space(text[end - 1])) --end;
  return text.substr(begin, end - begin);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

enum class NumberParse { kOk, kNotANumber, kOutOfRange };

// Parses a whole field as a double (locale independent); "nan" and "inf" parse as such.
NumberParse parse_number(const std::string& field, double& value) {
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (begin != end && *begin == '+') {  // from_chars rejects a leading '+'
    ++begin;
    if (begin == end || *begin == '+' || *begin == '-') return NumberParse::kNotANumber;
  }
  const auto result = std::from_chars(begin, end, value);
  if (begin == end || result.ptr != end) return NumberParse::kNotANumber;
  if (result.ec == std::errc::result_out_of_range) return NumberParse::kOutOfRange;
  return result.ec == std::errc() ? NumberParse::kOk : NumberParse::kNotANumber;
}

std::string read_text(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw DataError(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) {
    throw DataError(path + ": is a directory, expected a CSV file");
  }
  std::string text;
  try {
    text = read_whole_file(path);  // a device, a pipe or a failing read: named, not hung
  } catch (const FileError& e) {
    throw DataError(e.what());
  }
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // UTF-8 byte order mark
  return text;
}

std::string join_columns(const std::vector<std::string>& columns) {
  std::string text;
  for (const auto& name : columns) text += (text.empty() ? "" : ", ") + name;
  return "[" + text + "]";
}

CsvTrajectory parse_csv(const std::string& path) {
  const std::string text = read_text(path);
  auto fail = [&](int line, const std::string& what) {
    return DataError(fmt::format("{}:{}: {}", path, line, what));
  };

  CsvTrajectory result;
  RawTrajectory& trajectory = result.trajectory;
  trajectory.source = path;
  std::vector<std::vector<double>> rows;

  std::istringstream lines(text);
  std::string line;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty()) continue;  // blank line
    const std::vector<std::string> fields = split_fields(line);

    if (result.header_line == 0) {
      result.header_line = line_number;
      std::map<std::string, std::size_t> seen;
      bool all_numbers = true;
      for (std::size_t i = 0; i < fields.size(); ++i) {
        const std::string& name = fields[i];
        if (name.empty()) {
          throw fail(line_number, fmt::format("empty column name in the header (column {} of {})",
                                              i + 1, fields.size()));
        }
        const auto [it, inserted] = seen.emplace(name, i);
        if (!inserted) {
          throw fail(line_number, fmt::format("duplicate column name '{}' in the header (columns "
                                              "{} and {})",
                                              name, it->second + 1, i + 1));
        }
        double ignored;
        all_numbers = all_numbers && parse_number(name, ignored) != NumberParse::kNotANumber;
      }
      if (all_numbers) {
        throw fail(line_number,
                   fmt::format("no header row: the first line '{}' holds only numbers; "
                               "add a header row naming the columns",
                               line));
      }
      trajectory.columns = fields;
      continue;
    }

    const std::size_t width = trajectory.columns.size();
    if (fields.size() != width) {
      throw fail(line_number,
                 fmt::format("ragged row: expected {} fields (as in the header), got {}", width,
                             fields.size()));
    }
    std::vector<double> row(width);
    for (std::size_t i = 0; i < width; ++i) {
      const NumberParse parsed = parse_number(fields[i], row[i]);
      if (parsed == NumberParse::kNotANumber) {
        throw fail(line_number, fmt::format("field {} (column '{}') is not a number: \"{}\"", i + 1,
                                            trajectory.columns[i], fields[i]));
      }
      if (parsed == NumberParse::kOutOfRange) {
        throw fail(line_number, fmt::format("value \"{}\" in column '{}' is out of the range of a "
                                            "double",
                                            fields[i], trajectory.columns[i]));
      }
      if (!std::isfinite(row[i])) {
        throw fail(line_number, fmt::format("non-finite value \"{}\" in column '{}'", fields[i],
                                            trajectory.columns[i]));
      }
    }
    rows.push_back(std::move(row));
  }

  if (result.header_line == 0) {
    throw fail(1,
               "empty file: expected a header row naming the columns, then one row per time "
               "step");
  }
  if (rows.empty()) throw fail(result.header_line, "no data rows after the header");

  const auto steps = static_cast<Eigen::Index>(rows.size());
  const auto width = static_cast<Eigen::Index>(trajectory.columns.size());
  trajectory.values.resize(steps, width);
  for (Eigen::Index t = 0; t < steps; ++t) {
    for (Eigen::Index j = 0; j < width; ++j) trajectory.values(t, j) = rows[t][j];
  }
  return result;
}

}  // namespace

RawTrajectory read_csv_trajectory(const std::string& path) { return parse_csv(path).trajectory; }

std::vector<RawTrajectory> read_csv_trajectories(const std::vector<std::string>& paths) {
  std::vector<RawTrajectory> trajectories;
  trajectories.reserve(paths.size());
  for (const auto& path : paths) {
    CsvTrajectory csv = parse_csv(path);
    if (!trajectories.empty() && csv.trajectory.columns != trajectories.front().columns) {
      const RawTrajectory& first = trajectories.front();
      throw DataError(fmt::format("{}:{}: columns {} differ from the columns {} of {}", path,
                                  csv.header_line, join_columns(csv.trajectory.columns),
                                  join_columns(first.columns), first.source));
    }
    trajectories.push_back(std::move(csv.trajectory));
  }
  return trajectories;
}

}  // namespace corrmp

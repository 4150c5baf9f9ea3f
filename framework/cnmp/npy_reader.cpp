// Reader for NumPy .npy demonstration files ([N, T, D] float arrays, the data format of the
// public CNMP code of Seker et al., RSS 2019). Format reference:
// https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html
#include "cnmp/npy_reader.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <type_traits>

#include "core/file_read.hpp"

namespace corrmp {
namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr std::size_t kMagicSize = 6;

// One value of the header dictionary: a string, a boolean, a tuple of integers, or anything else
// (kept as raw text for messages, e.g. the list describing a structured dtype).
struct HeaderValue {
  enum class Kind { kString, kBool, kTuple, kOther } kind = Kind::kOther;
  std::string text;  // string contents, or raw source text for every other kind
  bool flag = false;
  std::vector<std::uint64_t> tuple;
};

struct NpyHeader {
  std::string descr;
  bool fortran_order = false;
  std::vector<std::uint64_t> shape;
};

// Replaces control characters (e.g. newlines from a corrupt header) so messages stay one line.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  }
  return text;
}

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  if (shape.size() == 1) return fmt::format("({},)", shape[0]);
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    text += (i == 0 ? "" : ", ") + std::to_string(shape[i]);
  }
  return text + ")";
}

// Parses the Python dict literal of a .npy header, e.g.
//   {'descr': '<f8', 'fortran_order': False, 'shape': (2, 50, 3), }
class HeaderParser {
 public:
  HeaderParser(const std::string& path, const std::string& text) : path_(path), text_(text) {}

  std::map<std::string, HeaderValue> parse() {
    std::map<std::string, HeaderValue> dict;
    skip_space();
    expect('{');
    while (true) {
      skip_space();
      if (peek() == '}') break;
      std::string key = parse_string();
      skip_space();
      expect(':');
      skip_space();
      dict[key] = parse_value();
      skip_space();
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      if (peek() != '}') fail("expected ',' or '}'");
      break;
    }
    ++pos_;  // the closing '}'
    skip_space();
    if (pos_ != text_.size()) fail("unexpected text after the dictionary");
    return dict;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw DataError(fmt::format("{}: malformed .npy header ({} at offset {}): {}", path_, what,
                                pos_, one_line(text_)));
  }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  void expect(char c) {
    if (peek() != c) fail(fmt::format("expected '{}'", c));
    ++pos_;
  }

  std::string parse_string() {
    const char quote = peek();
    if (quote != '\'' && quote != '"') fail("expected a quoted string");
    const std::size_t end = text_.find(quote, pos_ + 1);
    if (end == std::string::npos) fail("unterminated string");
    std::string value = text_.substr(pos_ + 1, end - pos_ - 1);
    pos_ = end + 1;
    return value;
  }

  std::uint64_t parse_integer() {
    const std::size_t start = pos_;
    std::uint64_t value = 0;
    while (std::isdigit(static_cast<unsigned char>(peek()))) {
      const std::uint64_t digit = static_cast<std::uint64_t>(peek() - '0');
      if (value > (std::numeric_limits<std::uint64_t>::max() - digit) / 10) {
        fail("dimension too large");
      }
      value = value * 10 + digit;
      ++pos_;
    }
    if (pos_ == start) fail("expected a non-negative integer");
    if (peek() == 'L') ++pos_;  // Python 2 long literal, e.g. (3L, 4L)
    return value;
  }

  // Skips a bracketed expression, returning its raw text.
  std::string skip_bracketed() {
    const std::size_t start = pos_;
    int depth = 0;
    do {
      const char c = peek();
      if (c == '\0') fail("unbalanced brackets");
      if (c == '\'' || c == '"') {
        parse_string();
        continue;
      }
      if (c == '[' || c == '(' || c == '{') ++depth;
      if (c == ']' || c == ')' || c == '}') --depth;
      ++pos_;
    } while (depth > 0);
    return text_.substr(start, pos_ - start);
  }

  HeaderValue parse_value() {
    HeaderValue value;
    const char c = peek();
    if (c == '\'' || c == '"') {
      value.kind = HeaderValue::Kind::kString;
      value.text = parse_string();
    } else if (text_.compare(pos_, 4, "True") == 0 || text_.compare(pos_, 5, "False") == 0) {
      value.kind = HeaderValue::Kind::kBool;
      value.flag = c == 'T';
      value.text = value.flag ? "True" : "False";
      pos_ += value.flag ? 4 : 5;
    } else if (c == '(') {
      value.kind = HeaderValue::Kind::kTuple;
      const std::size_t start = pos_++;
      while (true) {
        skip_space();
        if (peek() == ')') break;
        value.tuple.push_back(parse_integer());
        skip_space();
        if (peek() == ',') {
          ++pos_;
          continue;
        }
        if (peek() != ')') fail("expected ',' or ')' in tuple");
      }
      ++pos_;
      value.text = text_.substr(start, pos_ - start);
    } else if (c == '[' || c == '{') {
      value.text = skip_bracketed();
    } else {
      fail("unsupported value");
    }
    return value;
  }

  const std::string& path_;
  const std::string& text_;
  std::size_t pos_ = 0;
};

std::string read_file_bytes(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw DataError(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) {
    throw DataError(path + ": is a directory, expected a .npy file");
  }
  std::string bytes;
  try {
    bytes = read_whole_file(path);  // a device, a pipe or a failing read: named, not hung
  } catch (const FileError& e) {
    throw DataError(e.what());
  }
  return bytes;
}

std::uint64_t read_le(const std::string& bytes, std::size_t offset, std::size_t size) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < size; ++i) {
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[offset + i])) << (8 * i);
  }
  return value;
}

// Validates the preamble and header; returns the header and sets `data_offset`.
NpyHeader parse_npy_header(const std::string& path, const std::string& bytes,
                           std::size_t& data_offset) {
  if (bytes.size() < kMagicSize + 2 || std::memcmp(bytes.data(), kMagic, kMagicSize) != 0) {
    throw DataError(path + ": not a .npy file (missing the \\x93NUMPY magic string)");
  }
  const int major = static_cast<unsigned char>(bytes[6]);
  const int minor = static_cast<unsigned char>(bytes[7]);
  if (major < 1 || major > 3 || minor != 0) {
    throw DataError(
        fmt::format("{}: unsupported .npy format version {}.{} (supported: 1.0, 2.0, 3.0)", path,
                    major, minor));
  }
  const std::size_t length_size = major == 1 ? 2 : 4;
  const std::size_t preamble = kMagicSize + 2 + length_size;
  if (bytes.size() < preamble) throw DataError(path + ": truncated .npy header");
  const std::uint64_t header_length = read_le(bytes, kMagicSize + 2, length_size);
  if (header_length > bytes.size() - preamble) {
    throw DataError(fmt::format(
        "{}: truncated .npy header: header declares {} bytes but only {} follow the preamble", path,
        header_length, bytes.size() - preamble));
  }
  data_offset = preamble + header_length;
  const std::string text = bytes.substr(preamble, header_length);

  const auto dict = HeaderParser(path, text).parse();
  auto field = [&](const char* key) -> const HeaderValue& {
    const auto it = dict.find(key);
    if (it == dict.end()) {
      throw DataError(
          fmt::format("{}: malformed .npy header (no '{}' entry): {}", path, key, one_line(text)));
    }
    return it->second;
  };
  auto expect_kind = [&](const char* key, HeaderValue::Kind kind, const char* kind_name) {
    const HeaderValue& value = field(key);
    if (value.kind != kind) {
      throw DataError(fmt::format("{}: malformed .npy header ('{}' is {}, expected {})", path, key,
                                  one_line(value.text), kind_name));
    }
    return value;
  };

  NpyHeader header;
  const HeaderValue& descr = field("descr");
  if (descr.kind != HeaderValue::Kind::kString) {
    throw DataError(fmt::format(
        "{}: unsupported dtype {} (structured arrays are not supported); expected little-endian "
        "float32 '<f4' or float64 '<f8'",
        path, one_line(descr.text)));
  }
  header.descr = descr.text;
  header.fortran_order =
      expect_kind("fortran_order", HeaderValue::Kind::kBool, "True or False").flag;
  header.shape = expect_kind("shape", HeaderValue::Kind::kTuple, "a tuple of integers").tuple;
  return header;
}

template <class Float>
Float decode(const std::string& bytes, std::size_t offset) {
  static_assert(sizeof(Float) == 4 || sizeof(Float) == 8);
  using Bits = std::conditional_t<sizeof(Float) == 4, std::uint32_t, std::uint64_t>;
  const Bits bits = static_cast<Bits>(read_le(bytes, offset, sizeof(Float)));
  Float value;
  std::memcpy(&value, &bits, sizeof(Float));
  return value;
}

}  // namespace

std::vector<RawTrajectory> read_npy_trajectories(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  std::size_t data_offset = 0;
  const NpyHeader header = parse_npy_header(path, bytes, data_offset);

  std::size_t item_size = 0;
  if (header.descr == "<f4") {
    item_size = 4;
  } else if (header.descr == "<f8") {
    item_size = 8;
  } else {
    throw DataError(fmt::format(
        "{}: unsupported dtype '{}'; expected little-endian float32 '<f4' or float64 '<f8' "
        "(convert with arr.astype('<f8'))",
        path, one_line(header.descr)));
  }
  if (header.fortran_order) {
    throw DataError(path +
                    ": Fortran-order arrays are not supported; save with np.ascontiguousarray");
  }

  const auto& shape = header.shape;
  if (shape.size() == 2) {  // [T, D] of one demonstration or [N, T] of 1-D ones: not guessed
    throw DataError(fmt::format(
        "{}: got a 2-D array of shape {}, expected a 3-D array [N, T, D] (N demonstrations of T "
        "steps and D columns); save one demonstration [T, D] as arr[None], N one-column "
        "demonstrations [N, T] as arr[..., None]",
        path, shape_text(shape)));
  }
  if (shape.size() != 3) {
    throw DataError(
        fmt::format("{}: expected a 3-D array [N, T, D], got shape {}", path, shape_text(shape)));
  }
  const std::uint64_t n = shape[0];
  const std::uint64_t t = shape[1];
  const std::uint64_t d = shape[2];
  if (n == 0) {
    throw DataError(
        fmt::format("{}: no trajectories (N = 0) in shape {} [N, T, D]", path, shape_text(shape)));
  }
  if (t == 0) {
    throw DataError(
        fmt::format("{}: no time steps (T = 0) in shape {} [N, T, D]", path, shape_text(shape)));
  }
  if (d == 0) {
    throw DataError(
        fmt::format("{}: no columns (D = 0) in shape {} [N, T, D]", path, shape_text(shape)));
  }

  const std::uint64_t actual = bytes.size() - data_offset;
  const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  if (t > max / d || t * d > max / n || t * d * n > max / item_size) {
    throw DataError(fmt::format("{}: shape {} is too large", path, shape_text(shape)));
  }
  const std::uint64_t expected = n * t * d * item_size;
  if (actual < expected) {
    throw DataError(
        fmt::format("{}: truncated data: expected {} bytes for shape {} of {}, found {}", path,
                    expected, shape_text(shape), header.descr, actual));
  }
  if (actual > expected) {
    throw DataError(
        fmt::format("{}: unexpected trailing data: expected {} bytes for shape {} of {}, found {}",
                    path, expected, shape_text(shape), header.descr, actual));
  }
  if (t > static_cast<std::uint64_t>(std::numeric_limits<Eigen::Index>::max()) ||
      d > static_cast<std::uint64_t>(std::numeric_limits<Eigen::Index>::max())) {
    throw DataError(fmt::format("{}: shape {} is too large", path, shape_text(shape)));
  }

  std::vector<std::string> columns;
  columns.reserve(d);
  for (std::uint64_t j = 0; j < d; ++j) columns.push_back("c" + std::to_string(j));

  std::vector<RawTrajectory> trajectories;
  trajectories.reserve(n);
  std::size_t offset = data_offset;
  for (std::uint64_t i = 0; i < n; ++i) {
    RawTrajectory trajectory;
    trajectory.source = fmt::format("{}[{}]", path, i);
    trajectory.columns = columns;
    trajectory.values.resize(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(d));
    for (std::uint64_t step = 0; step < t; ++step) {
      for (std::uint64_t j = 0; j < d; ++j, offset += item_size) {
        const double value = item_size == 4 ? static_cast<double>(decode<float>(bytes, offset))
                                            : decode<double>(bytes, offset);
        if (!std::isfinite(value)) {
          throw DataError(
              fmt::format("{}: non-finite value {} at trajectory {}, time step {}, column c{}",
                          path, value, i, step, j));
        }
        trajectory.values(static_cast<Eigen::Index>(step), static_cast<Eigen::Index>(j)) = value;
      }
    }
    trajectories.push_back(std::move(trajectory));
  }
  return trajectories;
}

}  // namespace corrmp

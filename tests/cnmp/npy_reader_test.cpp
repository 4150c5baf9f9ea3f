// Tests of cnmp/npy_reader.hpp: reading [N, T, D] float32/float64 .npy demonstration files (the
// data format of the public CNMP code of Seker et al., RSS 2019) written from C++ here, and the
// one-line DataError message for every kind of bad file (2-D arrays included).
#include "cnmp/npy_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace corrmp {
namespace {

namespace fs = std::filesystem;

// Header text of a .npy file as NumPy writes it.
std::string header_dict(const std::string& descr, const std::string& shape,
                        bool fortran_order = false) {
  return "{'descr': '" + descr + "', 'fortran_order': " + (fortran_order ? "True" : "False") +
         ", 'shape': " + shape + ", }";
}

// A complete .npy file: magic, version, header length (uint16 for 1.0, uint32 for 2.0 / 3.0),
// the dict padded with spaces and a final '\n' to a multiple of 64 bytes, then `data`.
std::string npy_file(const std::string& dict, const std::string& data, int major = 1) {
  const std::size_t length_size = major == 1 ? 2 : 4;
  const std::size_t preamble = 6 + 2 + length_size;
  std::string header = dict;
  while ((preamble + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string bytes = "\x93NUMPY";
  bytes += static_cast<char>(major);
  bytes += '\0';
  for (std::size_t i = 0; i < length_size; ++i) {
    bytes += static_cast<char>((header.size() >> (8 * i)) & 0xff);
  }
  return bytes + header + data;
}

// Little-endian bytes of `values` as float32 or float64 (the test machine is little-endian).
template <class Float>
std::string encode(const std::vector<double>& values) {
  std::string bytes;
  for (double v : values) {
    const Float f = static_cast<Float>(v);
    char raw[sizeof(Float)];
    std::memcpy(raw, &f, sizeof(Float));
    bytes.append(raw, sizeof(Float));
  }
  return bytes;
}

// value(n, t, d) = 100 n + 10 t + d + 0.5, stored in C order.
std::vector<double> patterned(int n, int t, int d) {
  std::vector<double> values;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < t; ++j) {
      for (int k = 0; k < d; ++k) values.push_back(100.0 * i + 10.0 * j + k + 0.5);
    }
  }
  return values;
}

class NpyReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static int counter = 0;
    dir_ = fs::temp_directory_path() / ("corrmp-npy-reader-test-" + std::to_string(::getpid()) +
                                        "-" + std::to_string(counter++));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  // The DataError message of reading `path`; checks it is one line starting with "path: ".
  static std::string error_of(const std::string& path) {
    try {
      read_npy_trajectories(path);
    } catch (const DataError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      return message;
    }
    ADD_FAILURE() << "no DataError for " << path;
    return "";
  }

  fs::path dir_;
};

TEST_F(NpyReaderTest, ReadsFloat64ArrayOfShapeNTD) {
  const std::string path = write(
      "demos.npy", npy_file(header_dict("<f8", "(2, 3, 2)"), encode<double>(patterned(2, 3, 2))));
  const auto trajectories = read_npy_trajectories(path);
  ASSERT_EQ(trajectories.size(), 2u);
  for (int n = 0; n < 2; ++n) {
    const RawTrajectory& trajectory = trajectories[n];
    EXPECT_EQ(trajectory.source, path + "[" + std::to_string(n) + "]");
    EXPECT_EQ(trajectory.columns, (std::vector<std::string>{"c0", "c1"}));
    ASSERT_EQ(trajectory.values.rows(), 3);
    ASSERT_EQ(trajectory.values.cols(), 2);
    for (int t = 0; t < 3; ++t) {
      for (int d = 0; d < 2; ++d) {
        EXPECT_EQ(trajectory.values(t, d), 100.0 * n + 10.0 * t + d + 0.5);
      }
    }
  }
}

TEST_F(NpyReaderTest, ReadsFloat32ArrayAsDoubles) {
  std::vector<double> values = patterned(3, 2, 4);
  values[5] = 0.1;  // not exactly representable: read back as the float32 value
  const std::string path =
      write("demos.npy", npy_file(header_dict("<f4", "(3, 2, 4)"), encode<float>(values)));
  const auto trajectories = read_npy_trajectories(path);
  ASSERT_EQ(trajectories.size(), 3u);
  EXPECT_EQ(trajectories[2].columns, (std::vector<std::string>{"c0", "c1", "c2", "c3"}));
  EXPECT_EQ(trajectories[0].values(1, 1), static_cast<double>(0.1f));
  EXPECT_EQ(trajectories[2].values(1, 3), 213.5);
  EXPECT_EQ(trajectories[1].values(0, 2), 102.5);
}

// [T, D] of one demonstration and [N, T] of one-column demonstrations look alike: refused, with
// the shape and how to save either as [N, T, D].
TEST_F(NpyReaderTest, TwoDimensionalArrayIsRefusedNamingItsShape) {
  const std::string path =
      write("one.npy", npy_file(header_dict("<f8", "(4, 3)"), encode<double>(patterned(1, 4, 3))));
  EXPECT_EQ(error_of(path),
            path +
                ": got a 2-D array of shape (4, 3), expected a 3-D array [N, T, D] (N "
                "demonstrations of T steps and D columns); save one demonstration [T, D] as "
                "arr[None], N one-column demonstrations [N, T] as arr[..., None]");
  const std::string empty = write("empty.npy", npy_file(header_dict("<f4", "(0, 2)"), ""));
  EXPECT_NE(error_of(empty).find("got a 2-D array of shape (0, 2), expected a 3-D array"),
            std::string::npos);
}

TEST_F(NpyReaderTest, ReadsVersion2And3Headers) {
  for (int major : {2, 3}) {
    const std::string path =
        write("v" + std::to_string(major) + ".npy",
              npy_file(header_dict("<f8", "(1, 2, 1)"), encode<double>({1.25, -2.5}), major));
    const auto trajectories = read_npy_trajectories(path);
    ASSERT_EQ(trajectories.size(), 1u) << "version " << major;
    EXPECT_EQ(trajectories[0].values(0, 0), 1.25);
    EXPECT_EQ(trajectories[0].values(1, 0), -2.5);
  }
}

TEST_F(NpyReaderTest, AcceptsOtherKeyOrderAndPython2LongShapes) {
  const std::string path =
      write("old.npy", npy_file("{'shape': (1L, 2L, 1L), 'fortran_order': False, 'descr': '<f4'}",
                                encode<float>({3.0, 4.0})));
  const auto trajectories = read_npy_trajectories(path);
  ASSERT_EQ(trajectories.size(), 1u);
  EXPECT_EQ(trajectories[0].values(1, 0), 4.0);
}

TEST_F(NpyReaderTest, MissingFileIsAnError) {
  const std::string path = (dir_ / "absent.npy").string();
  EXPECT_NE(error_of(path).find("no such file"), std::string::npos);
}

TEST_F(NpyReaderTest, BadMagicIsAnError) {
  const std::string path = write("bad.npy", "PK\x03\x04 this is a zip archive");
  EXPECT_NE(error_of(path).find("not a .npy file"), std::string::npos);
}

TEST_F(NpyReaderTest, UnsupportedVersionIsAnError) {
  const std::string path =
      write("v4.npy", npy_file(header_dict("<f8", "(1, 1, 1)"), encode<double>({1.0}), 4));
  EXPECT_NE(error_of(path).find("unsupported .npy format version 4.0"), std::string::npos);
}

TEST_F(NpyReaderTest, UnsupportedDtypesAreNamed) {
  for (const std::string descr : {"<i8", ">f8", "|u1", "<f2"}) {
    const std::string path =
        write("dtype.npy", npy_file(header_dict(descr, "(1, 1, 1)"), std::string(8, '\0')));
    EXPECT_NE(error_of(path).find("unsupported dtype '" + descr + "'"), std::string::npos);
  }
}

TEST_F(NpyReaderTest, StructuredDtypeIsAnError) {
  const std::string path =
      write("rec.npy", npy_file("{'descr': [('x', '<f8'), ('y', '<f8')], 'fortran_order': False, "
                                "'shape': (1, 1, 1), }",
                                std::string(16, '\0')));
  const std::string message = error_of(path);
  EXPECT_NE(message.find("unsupported dtype [('x', '<f8'), ('y', '<f8')]"), std::string::npos);
  EXPECT_NE(message.find("structured arrays"), std::string::npos);
}

TEST_F(NpyReaderTest, FortranOrderIsAnError) {
  const std::string path = write(
      "f.npy", npy_file(header_dict("<f8", "(1, 2, 2)", true), encode<double>(patterned(1, 2, 2))));
  EXPECT_EQ(error_of(path),
            path + ": Fortran-order arrays are not supported; save with np.ascontiguousarray");
}

TEST_F(NpyReaderTest, WrongNumberOfDimensionsNamesTheShape) {
  const std::string one_d =
      write("1d.npy", npy_file(header_dict("<f8", "(6,)"), encode<double>(patterned(1, 1, 6))));
  EXPECT_NE(error_of(one_d).find("expected a 3-D array [N, T, D]"), std::string::npos);
  EXPECT_NE(error_of(one_d).find("got shape (6,)"), std::string::npos);
  const std::string four_d = write(
      "4d.npy", npy_file(header_dict("<f8", "(1, 2, 3, 1)"), encode<double>(patterned(1, 2, 3))));
  EXPECT_NE(error_of(four_d).find("got shape (1, 2, 3, 1)"), std::string::npos);
  const std::string scalar =
      write("0d.npy", npy_file(header_dict("<f8", "()"), encode<double>({1.0})));
  EXPECT_NE(error_of(scalar).find("got shape ()"), std::string::npos);
}

TEST_F(NpyReaderTest, ZeroSizedDimensionsAreErrors) {
  const std::string no_n = write("n.npy", npy_file(header_dict("<f8", "(0, 3, 2)"), ""));
  EXPECT_NE(error_of(no_n).find("no trajectories (N = 0) in shape (0, 3, 2)"), std::string::npos);
  const std::string no_t = write("t.npy", npy_file(header_dict("<f8", "(2, 0, 2)"), ""));
  EXPECT_NE(error_of(no_t).find("no time steps (T = 0) in shape (2, 0, 2)"), std::string::npos);
  const std::string no_d = write("d.npy", npy_file(header_dict("<f4", "(2, 3, 0)"), ""));
  EXPECT_NE(error_of(no_d).find("no columns (D = 0) in shape (2, 3, 0)"), std::string::npos);
}

TEST_F(NpyReaderTest, TruncatedDataReportsExpectedAndActualBytes) {
  std::string data = encode<double>(patterned(2, 3, 1));  // 48 bytes
  data.resize(40);
  const std::string path = write("short.npy", npy_file(header_dict("<f8", "(2, 3, 1)"), data));
  EXPECT_NE(error_of(path).find("truncated data: expected 48 bytes for shape (2, 3, 1) of <f8, "
                                "found 40"),
            std::string::npos);
}

TEST_F(NpyReaderTest, TrailingDataIsAnError) {
  const std::string path =
      write("long.npy", npy_file(header_dict("<f4", "(1, 2, 1)"), encode<float>({1.0, 2.0, 3.0})));
  EXPECT_NE(error_of(path).find("unexpected trailing data: expected 8 bytes"), std::string::npos);
}

TEST_F(NpyReaderTest, TruncatedHeaderIsAnError) {
  std::string bytes = npy_file(header_dict("<f8", "(1, 1, 1)"), "");
  bytes.resize(30);
  const std::string path = write("cut.npy", bytes);
  EXPECT_NE(error_of(path).find("truncated .npy header: header declares 118 bytes but only 20 "
                                "follow the preamble"),
            std::string::npos);
}

TEST_F(NpyReaderTest, MalformedHeaderIsAnError) {
  const std::string no_shape = write(
      "noshape.npy", npy_file("{'descr': '<f8', 'fortran_order': False}", encode<double>({1.0})));
  EXPECT_NE(error_of(no_shape).find("malformed .npy header (no 'shape' entry)"), std::string::npos);
  const std::string garbage = write("garbage.npy", npy_file("descr=<f8", encode<double>({1.0})));
  EXPECT_NE(error_of(garbage).find("malformed .npy header (expected '{'"), std::string::npos);
  const std::string negative =
      write("neg.npy", npy_file(header_dict("<f8", "(-1, 2, 1)"), encode<double>({1.0, 2.0})));
  EXPECT_NE(error_of(negative).find("malformed .npy header"), std::string::npos);
}

TEST_F(NpyReaderTest, NonFiniteValuesNameTrajectoryStepAndColumn) {
  std::vector<double> values = patterned(3, 4, 2);
  values[(2 * 4 + 1) * 2 + 1] = std::numeric_limits<double>::quiet_NaN();  // n=2, t=1, d=1
  const std::string f8 =
      write("nan.npy", npy_file(header_dict("<f8", "(3, 4, 2)"), encode<double>(values)));
  EXPECT_EQ(error_of(f8), f8 + ": non-finite value nan at trajectory 2, time step 1, column c1");

  values = patterned(3, 4, 2);
  values[(1 * 4 + 3) * 2 + 0] = -std::numeric_limits<double>::infinity();  // n=1, t=3, d=0
  const std::string f4 =
      write("inf.npy", npy_file(header_dict("<f4", "(3, 4, 2)"), encode<float>(values)));
  EXPECT_EQ(error_of(f4), f4 + ": non-finite value -inf at trajectory 1, time step 3, column c0");
}

}  // namespace
}  // namespace corrmp

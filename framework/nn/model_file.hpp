// Trained-model files: architecture hyperparameters plus named float32 tensors, written after
// training (CNMPs, autoencoder) and read back for evaluation, with corruption detection.
//
// Format "CMPM", version 1. All integers and floats are little-endian, independent of the host;
// a string is a uint32 byte count followed by that many UTF-8 bytes (no terminator).
//   offset 0       4 bytes   magic "CMPM"
//   offset 4       uint32    format version (1)
//   offset 8       uint64    body size B in bytes
//   offset 16      B bytes   body:
//                              uint32 H, then H x (string key, string value), keys ascending
//                              uint32 T, then T x tensor:
//                                string name, uint32 rank R, R x int64 dims (each >= 0),
//                                prod(dims) x float32 values (row-major, PyTorch order)
//   offset 16 + B  uint64    FNV-1a 64 hash (offset basis 0xcbf29ce484222325, prime
//                            0x100000001b3) of bytes [0, 16 + B)
// Readers reject, with a one-line std::runtime_error "model file '<path>': <problem>": a
// missing or unreadable file, a directory or other non-regular file, wrong magic, a version of
// 0 or newer than kFormatVersion, a file shorter than its header says (truncated), trailing
// bytes, a checksum mismatch, and a body whose structure does not add up. write() goes through
// core/atomic_file (a temporary name of the writer's own, checked writes, fsync, rename), so a
// crash or a full disk never leaves a half-written model under the final name.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "nn/parameter.hpp"

namespace corrmp::nn {

struct NamedTensor {
  std::string name;
  std::vector<std::int64_t> shape;
  std::vector<float> data;  ///< numel() values in row-major order

  std::int64_t numel() const;
};

// A model file that cannot be used: missing, unreadable, corrupt, or not the model a reader
// expects. what() is "model file '<path>': <problem>".
class ModelFileError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ModelFile {
  static constexpr std::uint32_t kFormatVersion = 1;

  std::map<std::string, std::string> hyper;  ///< architecture hyperparameters
  std::vector<NamedTensor> tensors;          ///< in file order, names unique
  std::string source = "<memory>";           ///< the path read from, used in error messages

  /// Writes the file atomically (core/atomic_file.hpp); throws std::runtime_error naming the
  /// path on failure, leaving a previous file there untouched, or on an invalid tensor
  /// (duplicate name, data size not matching its shape).
  void write(const std::string& path) const;
  /// Reads and validates a file; throws ModelFileError naming the path and the problem.
  static ModelFile read(const std::string& path);

  void set_hyper_int(const std::string& key, std::int64_t value);
  void set_hyper_double(const std::string& key, double value);  ///< shortest exact decimal
  /// The value of `key`; throws std::runtime_error if it is missing or not of that type.
  const std::string& hyper_string(const std::string& key) const;
  std::int64_t hyper_int(const std::string& key) const;
  double hyper_double(const std::string& key) const;

  /// The tensor called `name`, or nullptr.
  const NamedTensor* find(const std::string& name) const;
  /// The tensor called `name`; throws std::runtime_error if it is missing or its shape differs
  /// from expected_shape.
  const NamedTensor& tensor(const std::string& name,
                            const std::vector<std::int64_t>& expected_shape) const;

  /// Appends one tensor per parameter (values rounded to float32); throws on duplicate names.
  template <class S>
  void add_parameters(const std::vector<Parameter<S>>& params);
  /// Copies the tensor of each parameter's name into it, checking its shape; throws
  /// std::runtime_error on a missing tensor or a shape mismatch (parameters are then unchanged).
  template <class S>
  void load_parameters(const std::vector<Parameter<S>>& params) const;
};

}  // namespace corrmp::nn

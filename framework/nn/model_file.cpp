// Reading and writing trained-model files (format in nn/model_file.hpp).
#include "nn/model_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cstring>
#include <limits>
#include <set>
#include <stdexcept>
#include <system_error>

#include "core/atomic_file.hpp"
#include "core/file_read.hpp"

namespace corrmp::nn {
namespace {

constexpr char kMagic[4] = {'C', 'M', 'P', 'M'};
constexpr std::size_t kHeaderSize = 16;   // magic, version, body size
constexpr std::size_t kChecksumSize = 8;  // trailing FNV-1a 64

using Bytes = std::string;  // raw file contents

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw ModelFileError(fmt::format("model file '{}': {}", path, problem));
}

std::uint64_t fnv1a64(const char* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(data[i]);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

std::string shape_string(const std::vector<std::int64_t>& shape) {
  return fmt::format("[{}]", fmt::join(shape, ", "));
}

// ---- encoding -----------------------------------------------------------------------------

void put_uint(Bytes& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
}

void put_string(Bytes& out, const std::string& s, const std::string& path) {
  if (s.size() > std::numeric_limits<std::uint32_t>::max()) fail(path, "string too long");
  put_uint(out, s.size(), 4);
  out += s;
}

void put_float(Bytes& out, float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  put_uint(out, bits, 4);
}

// ---- decoding -----------------------------------------------------------------------------

class ByteReader {
 public:
  ByteReader(const Bytes& bytes, std::size_t begin, std::size_t end, const std::string& path)
      : bytes_(bytes), pos_(begin), end_(end), path_(path) {}

  std::uint64_t uint(int n, const char* what) {
    need(static_cast<std::size_t>(n), what);
    std::uint64_t value = 0;
    for (int i = 0; i < n; ++i)
      value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[pos_ + i])) << (8 * i);
    pos_ += static_cast<std::size_t>(n);
    return value;
  }
  std::string string(const char* what) {
    const std::size_t size = uint(4, what);
    need(size, what);
    std::string s = bytes_.substr(pos_, size);
    pos_ += size;
    return s;
  }
  float float32() {
    const auto bits = static_cast<std::uint32_t>(uint(4, "tensor values"));
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  std::size_t remaining() const { return end_ - pos_; }
  std::size_t position() const { return pos_; }
  [[noreturn]] void malformed(const std::string& problem) const {
    fail(path_, fmt::format("malformed body at byte {}: {}", pos_, problem));
  }

 private:
  void need(std::size_t n, const char* what) const {
    if (n > remaining())
      malformed(fmt::format("{} needs {} bytes, only {} left in the body", what, n, remaining()));
  }

  const Bytes& bytes_;
  std::size_t pos_;
  std::size_t end_;
  const std::string& path_;
};

Bytes read_all(const std::string& path) {
  try {
    return read_whole_file(path);
  } catch (const FileError& e) {
    fail(path, e.problem());  // "is a directory", "cannot open for reading: ...", ...
  }
}

void check_tensor(const NamedTensor& t, const std::string& path) {
  if (t.name.empty()) fail(path, "tensor with an empty name");
  for (std::int64_t d : t.shape)
    if (d < 0) fail(path, fmt::format("tensor '{}' has a negative dimension", t.name));
  if (t.numel() != static_cast<std::int64_t>(t.data.size()))
    fail(path, fmt::format("tensor '{}' has shape {} but {} values", t.name, shape_string(t.shape),
                           t.data.size()));
}

NamedTensor read_tensor(ByteReader& r) {
  NamedTensor t;
  t.name = r.string("tensor name");
  const std::uint64_t rank = r.uint(4, "tensor rank");
  if (rank > r.remaining() / 8)
    r.malformed(fmt::format("tensor '{}' rank {} too large", t.name, rank));
  std::uint64_t count = 1;
  for (std::uint64_t i = 0; i < rank; ++i) {
    const auto d = static_cast<std::int64_t>(r.uint(8, "tensor dimension"));
    if (d < 0) r.malformed(fmt::format("tensor '{}' has a negative dimension", t.name));
    t.shape.push_back(d);
    if (d != 0 && count > r.remaining() / 4 / static_cast<std::uint64_t>(d))
      r.malformed(fmt::format("tensor '{}' of shape {}... exceeds the body", t.name,
                              shape_string(t.shape)));
    count *= static_cast<std::uint64_t>(d);
  }
  if (count > r.remaining() / 4)
    r.malformed(fmt::format("tensor '{}' values exceed the body", t.name));
  t.data.resize(count);
  for (float& v : t.data) v = r.float32();
  return t;
}

}  // namespace

std::int64_t NamedTensor::numel() const {
  std::int64_t n = 1;
  for (std::int64_t d : shape) n *= d;
  return n;
}

void ModelFile::write(const std::string& path) const {
  std::set<std::string> names;
  for (const NamedTensor& t : tensors) {
    check_tensor(t, path);
    if (!names.insert(t.name).second) fail(path, fmt::format("duplicate tensor '{}'", t.name));
  }
  Bytes body;
  put_uint(body, hyper.size(), 4);
  for (const auto& [key, value] : hyper) {
    put_string(body, key, path);
    put_string(body, value, path);
  }
  put_uint(body, tensors.size(), 4);
  for (const NamedTensor& t : tensors) {
    put_string(body, t.name, path);
    put_uint(body, t.shape.size(), 4);
    for (std::int64_t d : t.shape) put_uint(body, static_cast<std::uint64_t>(d), 8);
    for (float v : t.data) put_float(body, v);
  }
  Bytes file(kMagic, sizeof kMagic);
  put_uint(file, kFormatVersion, 4);
  put_uint(file, body.size(), 8);
  file += body;
  put_uint(file, fnv1a64(file.data(), file.size()), 8);

  try {
    write_file_atomically(path, file);
  } catch (const FileError& e) {
    // The temporary file is gone and `path` is as it was; a write failure (a full disk) is not
    // a bad model file.
    throw std::runtime_error(fmt::format("model file '{}': {}", path, e.problem()));
  }
}

ModelFile ModelFile::read(const std::string& path) {
  const Bytes bytes = read_all(path);
  const std::size_t size = bytes.size();
  if (size >= sizeof kMagic && std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    fail(path, "wrong magic bytes (not a CMPM model file)");
  if (size < kHeaderSize + kChecksumSize)
    fail(path, fmt::format("truncated: {} bytes, shorter than the {}-byte header and checksum",
                           size, kHeaderSize + kChecksumSize));
  ByteReader header(bytes, sizeof kMagic, kHeaderSize, path);
  const auto version = static_cast<std::uint32_t>(header.uint(4, "version"));
  if (version == 0 || version > kFormatVersion)
    fail(path, fmt::format("format version {} is not supported (this build reads 1..{})", version,
                           kFormatVersion));
  const std::uint64_t body_size = header.uint(8, "body size");
  const std::uint64_t available = size - kHeaderSize - kChecksumSize;
  if (body_size > available)
    fail(path, fmt::format("truncated: {} bytes, the header announces {}", size,
                           body_size + kHeaderSize + kChecksumSize));
  if (body_size < available)
    fail(path,
         fmt::format("{} unexpected trailing bytes after the checksum", available - body_size));
  const std::size_t body_end = kHeaderSize + static_cast<std::size_t>(body_size);
  ByteReader checksum_reader(bytes, body_end, size, path);
  const std::uint64_t stored = checksum_reader.uint(8, "checksum");
  const std::uint64_t computed = fnv1a64(bytes.data(), body_end);
  if (stored != computed)
    fail(path, fmt::format("checksum mismatch (stored {:016x}, computed {:016x}): file is corrupt",
                           stored, computed));

  ModelFile model;
  model.source = path;
  ByteReader body(bytes, kHeaderSize, body_end, path);
  const std::uint64_t hyper_count = body.uint(4, "hyperparameter count");
  for (std::uint64_t i = 0; i < hyper_count; ++i) {
    std::string key = body.string("hyperparameter key");
    std::string value = body.string("hyperparameter value");
    if (!model.hyper.emplace(std::move(key), std::move(value)).second)
      body.malformed("duplicate hyperparameter key");
  }
  const std::uint64_t tensor_count = body.uint(4, "tensor count");
  std::set<std::string> names;
  for (std::uint64_t i = 0; i < tensor_count; ++i) {
    NamedTensor t = read_tensor(body);
    if (!names.insert(t.name).second) body.malformed(fmt::format("duplicate tensor '{}'", t.name));
    model.tensors.push_back(std::move(t));
  }
  if (body.remaining() != 0)
    body.malformed(fmt::format("{} unused bytes at the end of the body", body.remaining()));
  return model;
}

void ModelFile::set_hyper_int(const std::string& key, std::int64_t value) {
  hyper[key] = std::to_string(value);
}

void ModelFile::set_hyper_double(const std::string& key, double value) {
  hyper[key] = fmt::format("{}", value);
}

const std::string& ModelFile::hyper_string(const std::string& key) const {
  const auto it = hyper.find(key);
  if (it == hyper.end()) fail(source, fmt::format("missing hyperparameter '{}'", key));
  return it->second;
}

std::int64_t ModelFile::hyper_int(const std::string& key) const {
  const std::string& text = hyper_string(key);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size())
    fail(source, fmt::format("hyperparameter '{}' = '{}' is not an integer", key, text));
  return value;
}

double ModelFile::hyper_double(const std::string& key) const {
  const std::string& text = hyper_string(key);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size())
    fail(source, fmt::format("hyperparameter '{}' = '{}' is not a number", key, text));
  return value;
}

const NamedTensor* ModelFile::find(const std::string& name) const {
  for (const NamedTensor& t : tensors)
    if (t.name == name) return &t;
  return nullptr;
}

const NamedTensor& ModelFile::tensor(const std::string& name,
                                     const std::vector<std::int64_t>& expected_shape) const {
  const NamedTensor* t = find(name);
  if (t == nullptr) fail(source, fmt::format("missing tensor '{}'", name));
  if (t->shape != expected_shape)
    fail(source, fmt::format("tensor '{}' has shape {}, expected {}", name, shape_string(t->shape),
                             shape_string(expected_shape)));
  return *t;
}

template <class S>
void ModelFile::add_parameters(const std::vector<Parameter<S>>& params) {
  for (const Parameter<S>& p : params) {
    if (find(p.name) != nullptr) fail(source, fmt::format("duplicate tensor '{}'", p.name));
    NamedTensor t{p.name, p.shape, std::vector<float>(static_cast<std::size_t>(p.size()))};
    for (Index i = 0; i < p.size(); ++i)
      t.data[static_cast<std::size_t>(i)] = static_cast<float>(p.value[i]);
    tensors.push_back(std::move(t));
  }
}

template <class S>
void ModelFile::load_parameters(const std::vector<Parameter<S>>& params) const {
  std::vector<const NamedTensor*> sources;
  for (const Parameter<S>& p : params) sources.push_back(&tensor(p.name, p.shape));
  for (std::size_t k = 0; k < params.size(); ++k)
    for (Index i = 0; i < params[k].size(); ++i)
      params[k].value[i] = static_cast<S>(sources[k]->data[static_cast<std::size_t>(i)]);
}

template void ModelFile::add_parameters<float>(const std::vector<Parameter<float>>&);
template void ModelFile::add_parameters<double>(const std::vector<Parameter<double>>&);
template void ModelFile::load_parameters<float>(const std::vector<Parameter<float>>&) const;
template void ModelFile::load_parameters<double>(const std::vector<Parameter<double>>&) const;

}  // namespace corrmp::nn

// The demonstration cache's binary format.
#include "experiment/demonstration_cache.hpp"

#include <fmt/format.h>

#include <spdlog/spdlog.h>

#include <cstring>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.hpp"
#include "core/file_read.hpp"
#include "core/seeds.hpp"

namespace corrmp {

namespace {

// An exception's message without the path, when it is a FileError that has one.
std::string problem_of(const std::exception& e) {
  if (const auto* file_error = dynamic_cast<const FileError*>(&e)) return file_error->problem();
  return e.what();
}

constexpr char kMagic[4] = {'C', 'M', 'P', 'D'};
constexpr uint32_t kVersion = 3;  // 3: the camera model of each image

class Writer {
 public:
  template <class T>
  void pod(const T& value) {
    out_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void bytes(const void* data, size_t size) {
    pod(static_cast<uint64_t>(size));
    if (size > 0) out_.append(static_cast<const char*>(data), size);
  }
  void string(const std::string& s) { bytes(s.data(), s.size()); }
  void matrix(const Eigen::MatrixXd& m) {
    pod(static_cast<uint64_t>(m.rows()));
    pod(static_cast<uint64_t>(m.cols()));
    if (m.size() > 0) {
      out_.append(reinterpret_cast<const char*>(m.data()), sizeof(double) * m.size());
    }
  }
  void image(const cv::Mat& mat) {
    std::vector<uchar> png;
    if (!mat.empty()) cv::imencode(".png", mat, png);
    bytes(png.data(), png.size());
  }
  void depth(const cv::Mat& mat) {  // CV_32FC1, raw
    pod(static_cast<uint32_t>(mat.rows));
    pod(static_cast<uint32_t>(mat.cols));
    for (int row = 0; row < mat.rows; ++row) {
      out_.append(reinterpret_cast<const char*>(mat.ptr<float>(row)), sizeof(float) * mat.cols);
    }
  }
  void camera(const std::optional<CameraView>& view) {
    pod(static_cast<uint8_t>(view.has_value()));
    if (!view) return;
    const CameraIntrinsics& k = view->intrinsics;
    pod(static_cast<int32_t>(k.width));
    pod(static_cast<int32_t>(k.height));
    for (double v : {k.fx, k.fy, k.cx, k.cy, k.near, k.far}) pod(v);
    const Eigen::Matrix4d pose = view->world_from_camera.matrix();
    out_.append(reinterpret_cast<const char*>(pose.data()), sizeof(double) * 16);
  }
  std::string& data() { return out_; }

 private:
  std::string out_;
};

class Reader {
 public:
  Reader(const std::string& data, const std::string& path) : data_(data), path_(path) {}
  template <class T>
  T pod() {
    T value;
    need(sizeof(T));
    std::memcpy(&value, data_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string string() {
    const auto size = pod<uint64_t>();
    need(size);
    std::string s = data_.substr(at_, size);
    at_ += size;
    return s;
  }
  Eigen::MatrixXd matrix() {
    const auto rows = pod<uint64_t>(), cols = pod<uint64_t>();
    need(rows * cols * sizeof(double));
    Eigen::MatrixXd m(rows, cols);
    // An empty matrix has no storage: memcpy must not see its null pointer.
    if (m.size() > 0) std::memcpy(m.data(), data_.data() + at_, sizeof(double) * m.size());
    at_ += sizeof(double) * m.size();
    return m;
  }
  cv::Mat image(int flags) {
    const std::string png = string();
    if (png.empty()) return cv::Mat();
    return cv::imdecode(std::vector<uchar>(png.begin(), png.end()), flags);
  }
  cv::Mat depth() {
    const auto rows = pod<uint32_t>(), cols = pod<uint32_t>();
    if (rows == 0 || cols == 0) return cv::Mat();
    need(uint64_t{rows} * cols * sizeof(float));
    cv::Mat mat(static_cast<int>(rows), static_cast<int>(cols), CV_32FC1);
    std::memcpy(mat.data, data_.data() + at_, sizeof(float) * rows * cols);
    at_ += sizeof(float) * rows * cols;
    return mat;
  }
  std::optional<CameraView> camera() {
    if (pod<uint8_t>() == 0) return std::nullopt;
    CameraView view;
    CameraIntrinsics& k = view.intrinsics;
    k.width = pod<int32_t>();
    k.height = pod<int32_t>();
    for (double* v : {&k.fx, &k.fy, &k.cx, &k.cy, &k.near, &k.far}) *v = pod<double>();
    Eigen::Matrix4d pose;
    for (int i = 0; i < 16; ++i) pose.data()[i] = pod<double>();
    view.world_from_camera.matrix() = pose;
    return view;
  }
  bool done() const { return at_ == data_.size(); }

 private:
  void need(uint64_t size) {
    if (size > data_.size() - at_) {
      throw std::runtime_error(fmt::format("demonstration cache '{}': truncated", path_));
    }
  }
  const std::string& data_;
  const std::string& path_;
  size_t at_ = 0;
};

void write_demo(Writer& w, const Demonstration& demo) {
  w.string(demo.scenario);
  w.string(demo.decision);
  w.pod(static_cast<uint32_t>(demo.segments.size()));
  for (const auto& s : demo.segments) {
    w.string(s.segment);
    w.matrix(s.x);
    w.matrix(s.y);
    w.matrix(s.context);
    w.pod(s.phase_begin);
    w.pod(s.phase_end);
    w.pod(static_cast<uint32_t>(s.start.state.size()));
    for (const auto& [key, value] : s.start.state) {
      w.string(key);
      w.pod(value);
    }
    w.image(s.start.rgb);
    w.depth(s.start.depth);
    w.camera(s.start.camera);
  }
}

Demonstration read_demo(Reader& r) {
  Demonstration demo;
  demo.scenario = r.string();
  demo.decision = r.string();
  const auto segments = r.pod<uint32_t>();
  for (uint32_t i = 0; i < segments; ++i) {
    SegmentTrajectory s;
    s.segment = r.string();
    s.x = r.matrix();
    s.y = r.matrix();
    s.context = r.matrix();
    s.phase_begin = r.pod<double>();
    s.phase_end = r.pod<double>();
    const auto entries = r.pod<uint32_t>();
    for (uint32_t k = 0; k < entries; ++k) {
      const std::string key = r.string();
      s.start.state[key] = r.pod<double>();
    }
    s.start.rgb = r.image(cv::IMREAD_UNCHANGED);
    s.start.depth = r.depth();
    s.start.camera = r.camera();
    demo.segments.push_back(std::move(s));
  }
  return demo;
}

}  // namespace

bool save_demonstrations(const std::string& path, const DemonstrationSplit& demos) {
  Writer w;
  w.data().append(kMagic, 4);
  w.pod(kVersion);
  w.pod(static_cast<uint64_t>(demos.train.size()));
  w.pod(static_cast<uint64_t>(demos.validation.size()));
  for (const auto* set : {&demos.train, &demos.validation}) {
    for (const auto& demo : *set) write_demo(w, demo);
  }
  w.pod(fnv1a64(w.data()));
  try {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    write_file_atomically(path, w.data());
    return true;
  } catch (const std::exception& e) {
    spdlog::warn("demonstration cache '{}' not written: {}", path, problem_of(e));
    return false;
  }
}

std::optional<DemonstrationSplit> load_demonstrations(const std::string& path) {
  const auto corrupt = [&](const std::string& what) {
    return std::runtime_error(fmt::format("demonstration cache '{}': {}", path, what));
  };
  std::error_code error;
  const auto status = std::filesystem::symlink_status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) return std::nullopt;
  std::string data;
  try {
    data = read_whole_file(path);
  } catch (const FileError& e) {
    throw corrupt(e.problem());  // "is a directory", "cannot open for reading: ..."
  }
  if (data.size() < 16 || data.compare(0, 4, kMagic, 4) != 0) {
    throw corrupt(data.empty() ? "empty file" : "not a cache file");
  }
  uint64_t stored = 0;
  std::memcpy(&stored, data.data() + data.size() - 8, 8);
  const std::string body = data.substr(0, data.size() - 8);
  if (fnv1a64(body) != stored) throw corrupt("checksum mismatch (truncated or damaged)");
  Reader r(body, path);
  r.pod<uint32_t>();  // magic
  if (r.pod<uint32_t>() != kVersion) throw corrupt("unsupported version");
  const auto train = r.pod<uint64_t>(), validation = r.pod<uint64_t>();
  DemonstrationSplit demos;
  for (uint64_t i = 0; i < train; ++i) demos.train.push_back(read_demo(r));
  for (uint64_t i = 0; i < validation; ++i) demos.validation.push_back(read_demo(r));
  if (!r.done()) throw corrupt("trailing data");
  return demos;
}

}  // namespace corrmp

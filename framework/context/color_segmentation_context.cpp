// The colour-segmented rope-end context (color_segmentation_context.hpp).
#include "context/color_segmentation_context.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "context/color_segmentation/camera_noise.hpp"
#include "context/color_segmentation/rope_end_locator.hpp"
#include "context/color_segmentation/segmentation_overlay.hpp"

namespace corrmp {

namespace {

Eigen::Vector3d state_vector(const Observation& observation,
                             const std::vector<std::string>& names) {
  return {observation.value(names[0]), observation.value(names[1]), observation.value(names[2])};
}

// The rope end seen in the observation's image (world frame), with noise
// applied to copies of the images first.
std::optional<LocatedBlob> locate(const Observation& observation,
                                  const ColorSegmentationParams& params, Rng& noise) {
  if (observation.rgb.empty() || observation.depth.empty() || !observation.camera) {
    throw std::runtime_error(
        "the color_segmentation context needs a camera image with depth and its camera model");
  }
  cv::Mat rgb = observation.rgb.clone(), depth = observation.depth.clone();
  add_camera_noise(rgb, depth, params, noise);
  return locate_colour_blob(rgb, depth, observation.camera->intrinsics,
                            observation.camera->world_from_camera, params);
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

ColorSegmentationContext::ColorSegmentationContext(const ColorSegmentationContextParams& params,
                                                   uint64_t noise_seed)
    : params_(params), noise_(noise_seed) {
  params_.segmentation.validate();
  if (!params_.truth_state.empty() && params_.truth_state.size() != 3) {
    throw std::invalid_argument("color_segmentation: truth_state needs 3 names or none");
  }
}

std::vector<std::string> ColorSegmentationContext::state_names() const {
  std::vector<std::string> names = params_.gripper_state;
  names.insert(names.end(), params_.truth_state.begin(), params_.truth_state.end());
  return names;
}

bool ColorSegmentationContext::wanted(const std::string& segment) const {
  return std::find(params_.segments.begin(), params_.segments.end(), segment) !=
         params_.segments.end();
}

Eigen::VectorXd ColorSegmentationContext::extract(const std::string& segment,
                                                  const Observation& observation) {
  if (!wanted(segment)) return Eigen::VectorXd();
  Accuracy& accuracy = evaluating_ ? evaluation_ : demonstrations_;
  ++accuracy.extractions;
  const Eigen::Vector3d gripper = state_vector(observation, params_.gripper_state);
  const std::optional<LocatedBlob> blob = locate(observation, params_.segmentation, noise_);
  if (!blob) {
    // Nothing seen: the context says "at the gripper", i.e. no correction.
    spdlog::debug("color_segmentation: no coloured object found at the start of '{}'", segment);
    return Eigen::VectorXd::Zero(3);
  }
  ++accuracy.found;
  const Eigen::Vector3d relative = blob->position_world - gripper;
  if (!params_.truth_state.empty()) {
    accuracy.errors_m.push_back((relative - state_vector(observation, params_.truth_state)).norm());
  }
  return relative;
}

void ColorSegmentationContext::add_metrics(const Accuracy& accuracy, const std::string& prefix,
                                           std::vector<Metric>& out) {
  if (accuracy.extractions == 0) return;
  out.push_back({prefix + "context_found_rate",
                 static_cast<double>(accuracy.found) / accuracy.extractions,
                 rate_metric(Better::higher)});
  if (accuracy.errors_m.empty()) return;
  out.push_back(
      {prefix + "context_error_median_mm", 1000.0 * median(accuracy.errors_m), error_metric("mm")});
  out.push_back({prefix + "context_error_max_mm",
                 1000.0 * *std::max_element(accuracy.errors_m.begin(), accuracy.errors_m.end()),
                 error_metric("mm")});
}

std::vector<Metric> ColorSegmentationContext::metrics() const {
  std::vector<Metric> out;
  add_metrics(evaluation_, "", out);
  add_metrics(demonstrations_, "demonstrations_", out);
  return out;
}

void ColorSegmentationContext::write_outputs(const std::string& directory,
                                             const std::vector<Demonstration>& demos) {
  int written = 0;
  Rng no_noise(0);
  ColorSegmentationParams clean = params_.segmentation;
  clean.rgb_noise_std = clean.depth_noise_std = 0.0;
  for (const auto& demo : demos) {
    for (const auto& segment : demo.segments) {
      if (written >= params_.figures) return;
      if (!wanted(segment.segment) || segment.start.rgb.empty() || !segment.start.camera) continue;
      const Observation& seen = segment.start;
      std::optional<Eigen::Vector3d> truth;
      if (!params_.truth_state.empty()) {
        truth = state_vector(seen, params_.gripper_state) + state_vector(seen, params_.truth_state);
      }
      const cv::Mat overlay =
          draw_segmentation_overlay(seen.rgb, locate(seen, clean, no_noise),
                                    seen.camera->intrinsics, seen.camera->world_from_camera, truth);
      std::filesystem::create_directories(directory);
      const std::string path = fmt::format("{}/segmentation_{}.png", directory, written++);
      if (!cv::imwrite(path, overlay)) spdlog::warn("cannot write {}", path);
    }
  }
}

}  // namespace corrmp

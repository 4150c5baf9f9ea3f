// An expert's demonstrations in memory (expert_memory.hpp).
#include "envs/expert_memory.hpp"

#include <fmt/format.h>

#include "envs/environment.hpp"

namespace corrmp {

namespace {

// A recorded image is RGB bytes and a float depth per pixel (data/observation.hpp).
constexpr double kImageBytesPerPixel = 3.0 + sizeof(float);
// A trajectory value (time or a column) is a double, plus the float copy training makes.
constexpr double kTrajectoryBytesPerValue = sizeof(double) + sizeof(float);
// The key the estimates name: the expert's number of training demonstrations.
constexpr const char* kDemonstrationsKey = "train";

}  // namespace

int64_t expert_longest_trajectory(const Environment* environment) {
  if (!environment) return 0;
  int64_t points = 0;
  for (const auto& segment : environment->segments()) points += segment.points;
  return points;
}

std::vector<MemoryNeed> expert_memory_needs(const Environment* environment,
                                            const ExpertRecording& recording) {
  if (!environment) return {};
  const double demonstrations = recording.demonstrations;
  const double columns = static_cast<double>(environment->report().trajectory_columns.size()) + 1;
  // Each segment, and the whole skill again.
  const double points = 2.0 * static_cast<double>(expert_longest_trajectory(environment));
  std::vector<MemoryNeed> needs{
      {demonstrations * points * columns * kTrajectoryBytesPerValue, kDemonstrationsKey,
       fmt::format("{} demonstrations of {} trajectory points", recording.demonstrations, points)}};
  const cv::Size camera = environment->camera_size();
  if (recording.images_per_demonstration > 0 && !camera.empty()) {
    const double images = demonstrations * recording.images_per_demonstration;
    needs.push_back({images * camera.area() * kImageBytesPerPixel, kDemonstrationsKey,
                     fmt::format("{} demonstrations x {} RGB-D images of {}x{} pixels",
                                 recording.demonstrations, recording.images_per_demonstration,
                                 camera.width, camera.height)});
  }
  return needs;
}

}  // namespace corrmp

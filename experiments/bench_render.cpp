// bench_render: speed of the simulated head camera (OSMesa off-screen RGB-D renderer),
// which takes the images the robot observes (paper Sec. IV-A: camera images for the
// "Learning the Context" autoencoder of Sec. III-B; Sec. IV-C: an RGB-D image of the rope). A
// corridor-push scene (table, two corridor walls, the pushed object, the gripper's two
// fingers and palm, target marker, robot base) is rendered and read back into cv::Mat
// RGB and metric depth; items_per_second is frames per second of wall-clock time.
// Sizes 64, 128, 256.
//
// Threads: Mesa's llvmpipe rasterises on LP_NUM_THREADS worker threads (default: one
// per CPU). main() sets LP_NUM_THREADS=1 before the first context exists, so the
// figures are for one rasterising core, unless LP_NUM_THREADS is already set in the
// environment: `LP_NUM_THREADS=2 bench_render` measures llvmpipe's threading on two
// cores, `LP_NUM_THREADS=0` rasterises in the calling thread. The value used is
// printed in the benchmark context.
#include <benchmark/benchmark.h>

#include "data/camera_model.hpp"
#include "sim/render/node_chain.hpp"
#include "sim/render/offscreen_renderer.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

namespace corrmp {
namespace {

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

// Robot at the origin facing +x, table top at z = 0.7, corridor ahead of the object.
RenderScene corridor_scene() {
  RenderScene scene;
  scene.background = Eigen::Vector3f(0.55f, 0.6f, 0.65f);
  const Eigen::Vector3f wood(0.6f, 0.45f, 0.3f);
  const Eigen::Vector3f wall(0.2f, 0.3f, 0.8f);
  const Eigen::Vector3f metal(0.7f, 0.7f, 0.72f);
  auto& items = scene.items;
  items.push_back({Box{Eigen::Vector3d(0.4, 0.6, 0.35)}, at(0.6, 0.0, 0.35), wood});
  items.push_back({Box{Eigen::Vector3d(0.12, 0.02, 0.04)}, at(0.78, 0.09, 0.74), wall});
  items.push_back({Box{Eigen::Vector3d(0.12, 0.02, 0.04)}, at(0.78, -0.07, 0.74), wall});
  items.push_back({Cylinder{0.03, 0.04}, at(0.55, 0.01, 0.74), Eigen::Vector3f(0.9f, 0.1f, 0.1f)});
  items.push_back({Box{Eigen::Vector3d(0.01, 0.008, 0.04)}, at(0.5, 0.04, 0.76), metal});
  items.push_back({Box{Eigen::Vector3d(0.01, 0.008, 0.04)}, at(0.5, -0.02, 0.76), metal});
  items.push_back({Box{Eigen::Vector3d(0.02, 0.05, 0.01)}, at(0.5, 0.01, 0.81), metal});
  items.push_back({Cylinder{0.02, 0.08}, at(0.5, 0.01, 0.90), Eigen::Vector3f(0.3f, 0.3f, 0.3f)});
  items.push_back({Box{Eigen::Vector3d(0.03, 0.03, 0.001)}, at(0.95, 0.01, 0.701),
                   Eigen::Vector3f(0.1f, 0.8f, 0.2f)});
  items.push_back({Cylinder{0.15, 0.35}, at(0.0, 0.0, 0.35), Eigen::Vector3f(0.9f, 0.9f, 0.9f)});
  return scene;
}

// The corridor scene plus a 40-node rope lying on the table (39 more capsules).
RenderScene rope_scene() {
  RenderScene scene = corridor_scene();
  std::vector<Eigen::Vector3d> nodes;
  for (int i = 0; i < 40; ++i) {
    const double s = i / 39.0;
    nodes.emplace_back(0.45 + 0.3 * s, -0.25 + 0.1 * std::sin(6.0 * s), 0.71);
  }
  add_node_chain(scene, nodes, 0.008, Eigen::Vector3f(1.0f, 0.5f, 0.0f));
  return scene;
}

void render_frames(benchmark::State& state, const RenderScene& scene) {
  const int size = int(state.range(0));
  const CameraIntrinsics intrinsics =
      CameraIntrinsics::from_vertical_fov(size, size, 60.0 * M_PI / 180.0);
  OffscreenRenderer renderer(intrinsics);
  const Eigen::Isometry3d head = look_at(Eigen::Vector3d(0.05, 0.0, 1.35),
                                         Eigen::Vector3d(0.65, 0.0, 0.7), Eigen::Vector3d::UnitZ());
  renderer.render(scene, head);  // llvmpipe compiles its shaders on first use
  for (auto _ : state) {
    RgbdImage image = renderer.render(scene, head);
    benchmark::DoNotOptimize(image.rgb.data);
    benchmark::DoNotOptimize(image.depth.data);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["primitives"] = double(scene.items.size());
}

void BM_render_corridor(benchmark::State& state) { render_frames(state, corridor_scene()); }
void BM_render_rope(benchmark::State& state) { render_frames(state, rope_scene()); }

// Real time: llvmpipe's worker threads do the rasterising, out of this thread's CPU time.
BENCHMARK(BM_render_corridor)
    ->Arg(64)
    ->Arg(128)
    ->Arg(256)
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_render_rope)
    ->Arg(64)
    ->Arg(128)
    ->Arg(256)
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace corrmp

int main(int argc, char** argv) {
  setenv("LP_NUM_THREADS", "1", /*overwrite=*/0);  // before any OSMesa context exists
  benchmark::AddCustomContext("LP_NUM_THREADS", std::getenv("LP_NUM_THREADS"));
  benchmark::AddCustomContext(
      "gl_renderer",
      corrmp::OffscreenRenderer(corrmp::CameraIntrinsics::from_vertical_fov(8, 8, 1.0))
          .gl_renderer());
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// Tests of the rope-end segmentation parameters (paper, Section IV-C): read strictly from
// YAML, out-of-range values rejected by the config reader and by validate().
#include "context/color_segmentation/color_segmentation_params.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "context/color_segmentation_context.hpp"
#include "core/config/config_reader.hpp"

namespace corrmp {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

ColorSegmentationParams read_text(const std::string& text) {
  ConfigNode root = ConfigNode::parse(text, "segmentation.yaml");
  ColorSegmentationParams params;
  ConfigReader::read(root, "", params);
  return params;
}

TEST(ColorSegmentationParams, ReadsFromYamlAndKeepsDefaults) {
  const ColorSegmentationParams params =
      read_text("hue_centre: 350\nmorphology_kernel: 5\nsurface_offset: 0.004\n");
  EXPECT_DOUBLE_EQ(params.hue_centre, 350.0);
  EXPECT_EQ(params.morphology_kernel, 5);
  EXPECT_DOUBLE_EQ(params.surface_offset, 0.004);
  EXPECT_DOUBLE_EQ(params.hue_half_width, ColorSegmentationParams().hue_half_width);
  EXPECT_NO_THROW(params.validate());
}

TEST(ColorSegmentationParams, ConfigRejectsOutOfRangeAndUnknown) {
  EXPECT_THROW(read_text("saturation_min: 1.5\n"), ConfigError);
  EXPECT_THROW(read_text("cluster: smallest\n"), ConfigError);
  EXPECT_THROW(read_text("hue_center: 10\n"), ConfigError);
}

TEST(ColorSegmentationParams, ValidateNamesTheBadField) {
  ColorSegmentationParams params;
  params.morphology_kernel = 2;
  EXPECT_THAT([&] { params.validate(); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("morphology_kernel")));
  params = ColorSegmentationParams();
  params.depth_noise_std = -0.1;
  EXPECT_THROW(params.validate(), std::invalid_argument);
}

// The state values the context reads are the task's: its config names them (no default).
TEST(ColorSegmentationContextParams, TheStateNamesComeFromTheConfig) {
  ConfigNode missing = ConfigNode::parse("segments: [cor]\n", "context.yaml");
  ColorSegmentationContextParams params;
  EXPECT_THROW(ConfigReader::read(missing, "", params), ConfigError);
  ConfigNode given = ConfigNode::parse("gripper_state: [gx, gy, gz]\n", "context.yaml");
  ConfigReader::read(given, "", params);
  EXPECT_EQ(params.gripper_state, (std::vector<std::string>{"gx", "gy", "gz"}));
  EXPECT_TRUE(params.truth_state.empty());
}

}  // namespace
}  // namespace corrmp

// Context extractor `color_segmentation` (paper, Section IV-C "Knotting with
// the real robot"): the rope end is found in the head camera's RGB-D image by
// colour segmentation and clustering, back-projected with the depth and the
// camera model, and given relative to the gripper mid-point, read from the
// observation's state (in simulation the true finger mid-point: as if the
// robot also saw its gripper, so a hand's drift shows in the context). Where
// the observation also holds the true relative position, the extractor
// measures its own accuracy against it, apart for the demonstrations and for
// the evaluation.
#pragma once

#include <string>
#include <vector>

#include "context/color_segmentation/color_segmentation_params.hpp"
#include "context/context_extractor.hpp"
#include "core/config/field_rule.hpp"

namespace corrmp {

struct ColorSegmentationContextParams {
  std::vector<std::string> segments{"cor"};
  ColorSegmentationParams segmentation;
  // The state values are the task's own names: its config gives them.
  std::vector<std::string> gripper_state;
  std::vector<std::string> truth_state;
  int figures = 6;

  template <class Fields>
  void describe(Fields& f) {
    f("segments", segments, "segments whose context is the coloured object seen at their start");
    f("segmentation", segmentation, "colour thresholds, cleaning, clustering and camera noise");
    f("gripper_state", gripper_state,
      "observation state values of the gripper mid-point [x, y, z] the context is relative to",
      required().size_is(3));
    f("truth_state", truth_state,
      "observation state values of the true relative position of the object, to measure the "
      "accuracy ([] when the observation has none)");
    f("figures", figures, "head-camera frames written with the segmentation overlaid",
      in_range(0, 100));
  }
};

class ColorSegmentationContext : public ContextExtractor {
 public:
  ColorSegmentationContext(const ColorSegmentationContextParams& params, uint64_t noise_seed);

  void fit(const std::vector<Demonstration>&, const ExtractorCache&, Rng&) override {}
  Eigen::VectorXd extract(const std::string& segment, const Observation& observation) override;
  std::vector<std::string> segments() const override { return params_.segments; }
  std::vector<std::string> state_names() const override;
  bool needs_images() const override { return true; }
  void write_outputs(const std::string& directory,
                     const std::vector<Demonstration>& demos) override;
  void start_evaluation() override { evaluating_ = true; }
  // Over the evaluation's extractions: context_found_rate (the rope end was
  // seen), context_error_median_mm and context_error_max_mm (of the seen
  // ones, against the true offset); the same prefixed demonstrations_ over
  // the demonstrations'.
  std::vector<Metric> metrics() const override;

 private:
  // Extractions and their accuracy, of one phase.
  struct Accuracy {
    int extractions = 0, found = 0;
    std::vector<double> errors_m;
  };

  bool wanted(const std::string& segment) const;
  static void add_metrics(const Accuracy& accuracy, const std::string& prefix,
                          std::vector<Metric>& out);

  ColorSegmentationContextParams params_;
  Rng noise_;
  bool evaluating_ = false;
  Accuracy demonstrations_, evaluation_;
};

}  // namespace corrmp

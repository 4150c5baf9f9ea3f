// Tests of the paper's figures in its reproduction report: ground truth against
// prediction for the first seed's runs of the corridor and rope experiments it names, and
// the files of those runs it copies, each skipped with a note when missing.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "config/test_files.hpp"
#include "paper/paper.hpp"
#include "report/reproduction_figures.hpp"
#include "support/figure_runs.hpp"

namespace corrmp {
namespace {

namespace fs = std::filesystem;
using testing::any_note;
using testing::contains;
using testing::files_in;
using testing::png_size;
using testing::run_of;
using testing::TempDir;
using testing::write_trajectories;

TEST(PaperFigures, TheReportsFiguresComeFromTheFirstSeedsRunsAndCopiedFiles) {
  TempDir dir;
  write_trajectories(dir, "pc0");
  dir.write("pc0/training_curves.csv",
            "network,update,loss,validation_error_mean,validation_error_max\npre,100,1,0.1,0.2\n");
  write_trajectories(dir, "pc1");
  dir.write("ae0/log.txt", "");
  cv::imwrite(dir.file("ae0/autoencoder_reconstructions.png"),
              cv::Mat(30, 40, CV_8UC3, cv::Scalar(10, 20, 30)));
  const std::vector<RunSummary> runs = {run_of(1, "corridor_pc", {{"seed", "1"}}, 0.5),
                                        run_of(2, "corridor_pc", {{"seed", "0"}}, 1.0),
                                        run_of(3, "corridor_ae", {{"seed", "0"}}, 0.5),
                                        run_of(4, "rope_color", {{"seed", "0"}}, 0.0)};
  RunFilesById files;
  files[1] = files_in(dir, "pc1");
  files[2] = files_in(dir, "pc0");
  files[3] = files_in(dir, "ae0");
  // Run 4 has no entry: a run the database names no directory for.
  const FigureSet set =
      reproduction_figures(runs, files, dir.file("report"),
                           load_paper(std::string(PROJECT_DIR) + "/assets/paper").figures);
  std::vector<std::string> paths;
  for (const auto& figure : set.figures) paths.push_back(figure.path);
  EXPECT_EQ(paths,
            (std::vector<std::string>{"figures/ground_truth_vs_prediction_corridor_pc.png",
                                      "figures/success_vs_experiment.png",
                                      "figures/training_curves_corridor_pc.png",
                                      "figures/autoencoder_reconstructions_corridor_ae.png"}));
  EXPECT_TRUE(contains(set.figures[0].caption, "corridor_pc run 2 (seed 0)"));
  EXPECT_EQ(png_size(dir.file("report/figures/autoencoder_reconstructions_corridor_ae.png")),
            cv::Size(40, 30));
  EXPECT_TRUE(any_note(set, "ground truth vs prediction (corridor_ae): skipped")) << set.notes[0];
  EXPECT_TRUE(any_note(set, "ground truth vs prediction (rope_color): skipped"));
  EXPECT_TRUE(any_note(set, "training curves (corridor_ae)"));
  EXPECT_TRUE(any_note(set, "knotting.png (rope_color): skipped"));
  EXPECT_TRUE(any_note(set, "segmentation_0.png (rope_color): skipped"));
  for (const auto& figure : set.figures) {
    EXPECT_GT(fs::file_size(dir.file("report/" + figure.path)), 0u) << figure.path;
  }
}

}  // namespace
}  // namespace corrmp

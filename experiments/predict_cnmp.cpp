// predict_cnmp: loads a CNMP model file and writes predicted means and standard
// deviations as CSV for given observations (start point, via-points, end
// point), context and query times. Paper, Section III-A.
#include <fmt/format.h>
#include <fmt/os.h>
#include <CLI/CLI.hpp>

#include <cmath>

#include <iostream>

#include "command_line.hpp"

#include "cnmp/cnmp_model.hpp"
#include "nn/model_file.hpp"

namespace {

constexpr const char* kExamples = R"(
Examples:
  predict_cnmp --model model.cnmp --obs 0,0.1,0.2,0.3 --context 0.5 --steps 100
  predict_cnmp --model model.cnmp --obs 0,0,0,0 --obs 1,0.3,0.1,0 --query 0,0.25,0.5 --out p.csv
Each --obs is one observation: the x values (time in [0, 1], then task parameters) followed by
the y values. The CSV has the columns x0.., mean0.., std0...
)";

std::vector<double> parse_numbers(const std::string& text, const char* what) {
  std::vector<double> values;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string field = text.substr(start, comma - start);
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    if (field.empty() || end != field.c_str() + field.size()) {
      throw std::invalid_argument(fmt::format("{} '{}': '{}' is not a number", what, text, field));
    }
    if (!std::isfinite(value)) {
      throw std::invalid_argument(
          fmt::format("{} '{}': '{}' is not a finite number", what, text, field));
    }
    values.push_back(value);
    start = comma + 1;
  }
  return values;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Predicts trajectories with a trained CNMP.", "predict_cnmp"};
  std::string model_path, context_text, query_text, out;
  std::vector<std::string> observations_text;
  int steps = 100;
  app.add_option("--model", model_path, "model file from train_cnmp")->required();
  app.add_option("--obs", observations_text, "an observation: x values then y values")->required();
  app.add_option("--context", context_text, "context values, comma-separated");
  app.add_option("--query", query_text, "query times, comma-separated (1-D x only)");
  app.add_option("--steps", steps, "evenly spaced query times in [0, 1] when --query is absent")
      ->capture_default_str()
      ->check(CLI::Range(2, 1000000));
  app.add_option("--out", out, "CSV file (default: standard output)");
  app.footer(kExamples);
  if (const auto exit_code = corrmp::parse_command_line(app, argc, argv)) return *exit_code;
  try {
    auto model = corrmp::CnmpModel::load(model_path);
    const auto& a = model->architecture();
    Eigen::MatrixXd observations(observations_text.size(), a.d_x + a.d_y);
    for (size_t i = 0; i < observations_text.size(); ++i) {
      const auto values = parse_numbers(observations_text[i], "--obs");
      if (static_cast<int>(values.size()) != a.d_x + a.d_y) {
        throw std::invalid_argument(
            fmt::format("--obs '{}': this model needs {} x and {} y values, got {} values",
                        observations_text[i], a.d_x, a.d_y, values.size()));
      }
      observations.row(i) = Eigen::Map<const Eigen::RowVectorXd>(values.data(), values.size());
    }
    const auto context_values =
        context_text.empty() ? std::vector<double>{} : parse_numbers(context_text, "--context");
    if (static_cast<int>(context_values.size()) != a.d_context) {
      throw std::invalid_argument(fmt::format("--context: this model needs {} values, got {}",
                                              a.d_context, context_values.size()));
    }
    const Eigen::VectorXd context =
        Eigen::Map<const Eigen::VectorXd>(context_values.data(), context_values.size());
    std::vector<double> times;
    if (query_text.empty()) {
      for (int i = 0; i < steps; ++i) times.push_back(static_cast<double>(i) / (steps - 1));
    } else {
      times = parse_numbers(query_text, "--query");
    }
    if (a.d_x != 1) {
      throw std::invalid_argument(fmt::format(
          "this model has {} inputs (time plus task parameters); predict_cnmp queries time only",
          a.d_x));
    }
    const Eigen::MatrixXd query = Eigen::Map<const Eigen::VectorXd>(times.data(), times.size());
    const corrmp::CnmpPrediction p = model->predict(observations, context, query);

    std::string csv = "x0";
    for (int i = 0; i < a.d_y; ++i) csv += fmt::format(",mean{}", i);
    for (int i = 0; i < a.d_y; ++i) csv += fmt::format(",std{}", i);
    csv += "\n";
    for (Eigen::Index t = 0; t < query.rows(); ++t) {
      csv += fmt::format("{}", query(t, 0));
      for (int i = 0; i < a.d_y; ++i) csv += fmt::format(",{}", p.mean(t, i));
      for (int i = 0; i < a.d_y; ++i) csv += fmt::format(",{}", p.std(t, i));
      csv += "\n";
    }
    if (out.empty()) {
      std::cout << csv;
    } else {
      fmt::output_file(out).print("{}", csv);
    }
    return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "predict_cnmp: " << e.what() << "\n";
    return 2;
  } catch (const corrmp::nn::ModelFileError& e) {  // bad input, like a bad option
    std::cerr << "predict_cnmp: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "predict_cnmp: " << e.what() << "\n";
    return 1;
  }
}

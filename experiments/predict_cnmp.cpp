// predict_cnmp: loads a CNMP model file and writes predicted means and standard
// deviations as CSV for given observations (start point, via-points, end
// point), context, query times and, for a model trained with task parameters
// (train_cnmp --x), their values at the query times; query times beyond the
// [0, 1] of training get a warning. Paper, Section III-A.
#include <fmt/format.h>
#include <fmt/os.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "command_line.hpp"

#include "cnmp/cnmp_model.hpp"
#include "core/path_checks.hpp"
#include "nn/model_file.hpp"

namespace {

constexpr const char* kExamples = R"(
Examples:
  predict_cnmp --model model.cnmp --obs 0,0.1,0.2,0.3 --context 0.5 --steps 100
  predict_cnmp --model model.cnmp --obs 0,0,0,0 --obs 1,0.3,0.1,0 --query 0,0.25,0.5 --out p.csv
  predict_cnmp --model speed.cnmp --obs 0,0.8,0,0 --x-values 0.8 --steps 50
Each --obs is one observation: the x values (time in [0, 1], then task parameters) followed by
the y values. A model trained with task parameters (train_cnmp --x) needs their values for the
query times, the same at every time: --x-values. The CSV has the columns x0.., mean0.., std0...
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

// The query inputs, one row per time: the time, then the task parameters' values.
Eigen::MatrixXd query_inputs(const std::vector<double>& times,
                             const std::vector<double>& task_values) {
  Eigen::MatrixXd query(static_cast<Eigen::Index>(times.size()),
                        1 + static_cast<Eigen::Index>(task_values.size()));
  query.col(0) = Eigen::Map<const Eigen::VectorXd>(times.data(), query.rows());
  for (Eigen::Index i = 1; i < query.cols(); ++i) {
    query.col(i).setConstant(task_values[static_cast<size_t>(i - 1)]);
  }
  return query;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Predicts trajectories with a trained CNMP.", "predict_cnmp"};
  std::string model_path, context_text, query_text, x_values_text, out;
  std::vector<std::string> observations_text;
  int steps = 100;
  app.add_option("--model", model_path, "model file from train_cnmp")->required();
  app.add_option("--obs", observations_text, "an observation: x values then y values")->required();
  app.add_option("--context", context_text, "context values, comma-separated");
  app.add_option("--query", query_text, "query times, comma-separated");
  app.add_option("--steps", steps, "evenly spaced query times in [0, 1] when --query is absent")
      ->capture_default_str()
      ->check(CLI::Range(2, 1000000));
  app.add_option("--x-values", x_values_text,
                 "task-parameter values at every query time, comma-separated (models trained "
                 "with train_cnmp --x)");
  app.add_option("--out", out, "CSV file (default: standard output)");
  app.footer(kExamples);
  if (const auto exit_code = corrmp::parse_command_line(app, argc, argv)) return *exit_code;
  if (!out.empty() && corrmp::same_file(out, model_path)) {
    std::cerr << fmt::format(
        "predict_cnmp: --out {}: is the model file (--model {}): write the predictions to another "
        "file\n",
        out, model_path);
    return 2;
  }
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
    const auto task_values =
        x_values_text.empty() ? std::vector<double>{} : parse_numbers(x_values_text, "--x-values");
    const int task_parameters = a.d_x - 1;
    if (static_cast<int>(task_values.size()) != task_parameters) {
      throw std::invalid_argument(
          task_parameters == 0
              ? fmt::format("--x-values: this model has no task parameters (it was trained "
                            "without train_cnmp --x), got {} values",
                            task_values.size())
              : fmt::format("--x-values: this model needs {} values, one per task parameter "
                            "(train_cnmp --x), got {}",
                            task_parameters, task_values.size()));
    }
    const auto [earliest, latest] = std::minmax_element(times.begin(), times.end());
    if (*earliest < 0.0 || *latest > 1.0) {
      std::cerr << fmt::format(
          "predict_cnmp: warning: query times span [{}, {}], beyond the normalised time range "
          "[0, 1] of the demonstrations; the prediction there is an extrapolation\n",
          *earliest, *latest);
    }
    const Eigen::MatrixXd query = query_inputs(times, task_values);
    const corrmp::CnmpPrediction p = model->predict(observations, context, query);

    std::string csv = "x0";
    for (int i = 1; i < a.d_x; ++i) csv += fmt::format(",x{}", i);
    for (int i = 0; i < a.d_y; ++i) csv += fmt::format(",mean{}", i);
    for (int i = 0; i < a.d_y; ++i) csv += fmt::format(",std{}", i);
    csv += "\n";
    for (Eigen::Index t = 0; t < query.rows(); ++t) {
      csv += fmt::format("{}", query(t, 0));
      for (int i = 1; i < a.d_x; ++i) csv += fmt::format(",{}", query(t, i));
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

// Trained CNMPs in data units, and their model files.
#include "cnmp/cnmp_model.hpp"

#include <fmt/format.h>

#include <random>

namespace corrmp {

namespace {

Cnmp<float> make_network(const CnmpArchitecture& architecture, uint64_t seed) {
  nn::Rng rng(seed);
  return Cnmp<float>(architecture, rng);
}

// Normalisers are stored as exact decimal hyperparameters (float32 tensors
// would round them), so a loaded model predicts exactly as the saved one.
void write_row(nn::ModelFile& file, const std::string& name, const Eigen::RowVectorXd& values) {
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    file.set_hyper_double(fmt::format("{}.{}", name, i), values[i]);
  }
}

Eigen::RowVectorXd read_row(const nn::ModelFile& file, const std::string& name, int size) {
  Eigen::RowVectorXd values(size);
  for (int i = 0; i < size; ++i) values[i] = file.hyper_double(fmt::format("{}.{}", name, i));
  return values;
}

}  // namespace

CnmpModel::CnmpModel(const CnmpArchitecture& architecture, uint64_t seed)
    : y_normaliser(Normaliser::identity(architecture.d_y)),
      context_normaliser(Normaliser::identity(architecture.d_context)),
      network_(make_network(architecture, seed)) {}

CnmpPrediction CnmpModel::predict(const Eigen::MatrixXd& observations,
                                  const Eigen::VectorXd& context, const Eigen::MatrixXd& query_x) {
  const auto& a = architecture();
  if (observations.cols() != a.d_x + a.d_y) {
    throw std::invalid_argument(fmt::format("observations need {} columns (x then y), got {}",
                                            a.d_x + a.d_y, observations.cols()));
  }
  if (context.size() != a.d_context) {
    throw std::invalid_argument(
        fmt::format("the context needs {} values, got {}", a.d_context, context.size()));
  }
  Eigen::MatrixXd obs = observations;
  obs.rightCols(a.d_y) = y_normaliser.apply(observations.rightCols(a.d_y));
  const nn::Mat<float> obs_f = obs.cast<float>();
  const nn::Mat<float> ctx_f = context_normaliser.apply(context.transpose()).cast<float>();
  const nn::Mat<float> query_f = query_x.cast<float>();
  nn::Mat<float> mean, std;
  network_.predict(obs_f, ctx_f, query_f, mean, std);
  CnmpPrediction out;
  out.mean = y_normaliser.invert(mean.cast<double>());
  out.std = (std.cast<double>().array().rowwise() * y_normaliser.scale.array()).matrix();
  return out;
}

void CnmpModel::save(const std::string& path) {
  nn::ModelFile file;
  network_.save_to(file);
  write_row(file, "normaliser.y_offset", y_normaliser.offset);
  write_row(file, "normaliser.y_scale", y_normaliser.scale);
  write_row(file, "normaliser.context_offset", context_normaliser.offset);
  write_row(file, "normaliser.context_scale", context_normaliser.scale);
  file.write(path);
}

std::unique_ptr<CnmpModel> CnmpModel::load(const std::string& path) {
  const nn::ModelFile file = nn::ModelFile::read(path);
  if (file.hyper.count("model") == 0 || file.hyper.at("model") != "cnmp") {
    throw nn::ModelFileError(fmt::format("model file '{}': not a CNMP model", path));
  }
  const CnmpArchitecture architecture = Cnmp<float>::architecture_of(file);
  auto model = std::make_unique<CnmpModel>(architecture, 0);
  model->network_.load_from(file);
  model->y_normaliser = {read_row(file, "normaliser.y_offset", architecture.d_y),
                         read_row(file, "normaliser.y_scale", architecture.d_y)};
  model->context_normaliser = {read_row(file, "normaliser.context_offset", architecture.d_context),
                               read_row(file, "normaliser.context_scale", architecture.d_context)};
  return model;
}

}  // namespace corrmp

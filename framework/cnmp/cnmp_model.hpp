// A trained CNMP in the units of its data: the network plus the normalisers of
// y and context, prediction from any set of observations (start point,
// via-points, end point) and a context at any query times, and its model file.
// Paper, Section III-A.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "cnmp/cnmp.hpp"
#include "cnmp/normaliser.hpp"

namespace corrmp {

struct CnmpPrediction {
  Eigen::MatrixXd mean;  // T x d_y
  Eigen::MatrixXd std;   // T x d_y
};

class CnmpModel {
 public:
  CnmpModel(const CnmpArchitecture& architecture, uint64_t seed);

  // observations: n x (d_x + d_y) rows (x then y); context: d_context values;
  // query_x: T x d_x. All in data units.
  CnmpPrediction predict(const Eigen::MatrixXd& observations, const Eigen::VectorXd& context,
                         const Eigen::MatrixXd& query_x);

  void save(const std::string& path);
  static std::unique_ptr<CnmpModel> load(const std::string& path);

  Cnmp<float>& network() { return network_; }
  const CnmpArchitecture& architecture() const { return network_.architecture(); }
  Normaliser y_normaliser;
  Normaliser context_normaliser;

 private:
  Cnmp<float> network_;
};

}  // namespace corrmp

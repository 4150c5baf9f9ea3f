// The paper's data, read (paper.hpp).
#include "paper/paper.hpp"

#include "core/config/config_loader.hpp"
#include "core/config/config_reader.hpp"

namespace corrmp {

std::string paper_directory() { return std::string(CORRMP_SOURCE_DIR) + "/assets/paper"; }

ReproductionSpec load_paper(const std::string& directory) {
  ConfigNode root = load_config_file(directory + "/report.yaml");
  ReproductionSpec spec;
  ConfigReader::read(root, "", spec);
  check_decision_tables(spec.decision_tables, *root.find("decision_tables"), "decision_tables");
  return spec;
}

}  // namespace corrmp

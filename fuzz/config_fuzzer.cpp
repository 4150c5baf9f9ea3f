// libFuzzer target for the config path that `run_experiment CONFIG --print-config`
// runs: config load (includes, overrides) and load_experiment with the real
// registries, which validates every section and builds every component.
//
// Input: the config text, optionally followed by a line "%%overrides" and one
// key.path=value override per line (at most kMaxOverrides). The text is written
// to input.yaml in a scratch copy of configs/, so that `include: [common/...]`
// finds the real fragments (in $CORRMP_FUZZ_SCRATCH, or a temporary directory). A ConfigError is
// the expected outcome of bad input; any other exception (uncaught, so libFuzzer reports it),
// crash, leak or sanitizer report is a finding. docs/architecture.md, "Configs"; scripts/fuzz.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/config/config_error.hpp"
#include "core/thread_budget.hpp"
#include "experiment/experiment.hpp"
#include "experiment/registries.hpp"

namespace {

namespace fs = std::filesystem;

constexpr const char* kSeparator = "\n%%overrides\n";
constexpr std::size_t kMaxOverrides = 8;

struct FuzzState {
  corrmp::Registries registries = corrmp::builtin_registries();
  fs::path scratch;
  std::string input_path;
};

FuzzState* state = nullptr;

void remove_scratch() {
  if (state == nullptr) return;
  std::error_code ignored;
  fs::remove_all(state->scratch, ignored);
}

// The config text and the overrides of one input.
void split_input(const std::string& data, std::string& text, std::vector<std::string>& overrides) {
  const auto separator = data.find(kSeparator);
  text = data.substr(0, separator);
  if (separator == std::string::npos) return;
  std::size_t at = separator + std::char_traits<char>::length(kSeparator);
  while (at <= data.size() && overrides.size() < kMaxOverrides) {
    const auto end = data.find('\n', at);
    overrides.push_back(data.substr(at, end == std::string::npos ? std::string::npos : end - at));
    if (end == std::string::npos) break;
    at = end + 1;
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  spdlog::set_level(spdlog::level::off);
  corrmp::set_thread_budget(1);
  state = new FuzzState;
  // scripts/fuzz names a directory it removes even after a crash.
  const char* scratch = std::getenv("CORRMP_FUZZ_SCRATCH");
  state->scratch =
      scratch != nullptr && *scratch != '\0'
          ? fs::path(scratch)
          : fs::temp_directory_path() / ("corrmp-config-fuzz-" + std::to_string(::getpid()));
  fs::remove_all(state->scratch);
  fs::create_directories(state->scratch);
  fs::copy(fs::path(CORRMP_SOURCE_DIR) / "configs", state->scratch / "configs",
           fs::copy_options::recursive);
  state->input_path = (state->scratch / "configs" / "input.yaml").string();
  std::atexit(remove_scratch);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string text;
  std::vector<std::string> overrides;
  split_input(std::string(reinterpret_cast<const char*>(data), size), text, overrides);
  {
    std::ofstream out(state->input_path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  try {
    const corrmp::Experiment experiment =
        corrmp::load_experiment(state->input_path, overrides, state->registries);
    // What --print-config prints; touch it so that it is computed in full.
    if (experiment.resolved_yaml.empty()) std::abort();
  } catch (const corrmp::ConfigError&) {
    // The expected outcome for bad input.
  }
  return 0;
}

// What every component factory receives besides its own parameters: the seed
// streams and where it may cache work. DESIGN.md, "Core interfaces".
#pragma once

#include <string>

#include "core/seeds.hpp"

namespace corrmp {

struct BuildContext {
  SeedTree seeds{0};
  std::string cache_dir = "results/cache";  // reusable artefacts keyed by content hash
};

}  // namespace corrmp

// What every component factory receives besides its own parameters: the seed
// streams. docs/architecture.md, "Components".
#pragma once

#include "core/seeds.hpp"

namespace corrmp {

struct BuildContext {
  SeedTree seeds{0};
};

}  // namespace corrmp

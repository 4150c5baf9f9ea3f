// What every component factory receives besides its own parameters: the seed
// streams. DESIGN.md, "Core interfaces".
#pragma once

#include "core/seeds.hpp"

namespace corrmp {

struct BuildContext {
  SeedTree seeds{0};
};

}  // namespace corrmp

// Loading scene descriptions.
#include "sim/scene_description.hpp"

#include <fmt/format.h>

#include <set>

#include "core/config/config_loader.hpp"
#include "core/config/config_reader.hpp"

namespace corrmp {

const SceneBodySpec& SceneDescription::body(const std::string& name) const {
  for (const auto& b : bodies) {
    if (b.name == name) return b;
  }
  throw std::runtime_error(fmt::format("the scene has no body called '{}'", name));
}

SceneDescription load_scene(const std::string& path) {
  ConfigNode root = load_config_file(path);
  SceneDescription scene;
  ConfigReader::read(root, "", scene);
  std::set<std::string> names;
  auto item = root.find("bodies")->items().begin();
  for (size_t i = 0; i < scene.bodies.size(); ++i, ++item) {
    const SceneBodySpec& b = scene.bodies[i];
    const std::string at = fmt::format("bodies[{}]", i);
    const size_t expected = b.shape == "box" ? 3 : b.shape == "sphere" ? 1 : 2;
    if (b.size.size() != expected) {
      throw ConfigError(
          item->find("size")->where(), at + ".size",
          fmt::format("a {} needs {} sizes, got {}", b.shape, expected, b.size.size()));
    }
    for (const char* key : {"position", "rpy", "colour"}) {
      const ConfigNode* node = item->find(key);
      if (node->items().size() != 3) {
        throw ConfigError(node->where(), at + "." + key, "expected 3 values");
      }
    }
    if (!names.insert(b.name).second) {
      throw ConfigError(item->find("name")->where(), at + ".name",
                        fmt::format("duplicate body name '{}'", b.name));
    }
  }
  return scene;
}

}  // namespace corrmp

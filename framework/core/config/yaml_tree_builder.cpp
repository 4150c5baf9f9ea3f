// ConfigNode trees from yaml-cpp parser events, with the checks and bounds of
// config_limits.hpp. docs/architecture.md, "Configs".
#include "core/config/yaml_tree_builder.hpp"

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "core/config/config_text.hpp"

namespace corrmp {

namespace {

SourceLocation location_of(const YAML::Mark& mark, const std::string& file) {
  if (mark.is_null()) return SourceLocation{file, 0, 0};
  return SourceLocation{file, mark.line + 1, mark.column + 1};
}

std::string child_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

// A list or map whose values are still being parsed.
struct OpenNode {
  ConfigNode node;
  std::string path;  // dotted key path of the node ("" for the root)
  YAML::anchor_t anchor = YAML::NullAnchor;
  std::size_t nodes_left_before = 0;  // the budget before this node was counted
  int height = 1;                     // levels of lists and maps, this one included
  // Maps: the keys so far, and the key whose value comes next.
  std::unordered_set<std::string> keys;
  bool has_key = false;
  std::string key;
  SourceLocation key_where;
};

// A value with an anchor (&name), copied wherever an alias (*name) refers to it.
struct Anchored {
  ConfigNode node;
  std::size_t nodes = 0;
  int height = 0;
  bool complete = false;  // false while its own values are being parsed
};

class TreeBuilder final : public YAML::EventHandler {
 public:
  TreeBuilder(const std::string& text, const std::string& file, ConfigBudget& budget,
              int base_depth)
      : text_(text), file_(file), budget_(budget), base_depth_(base_depth) {
    root_.set_where(SourceLocation{file, 0, 0});
  }

  ConfigNode take_root() { return std::move(root_); }

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1) {
      throw ConfigError(second_document_location(mark), "",
                        "a second YAML document: a config file holds exactly one");
    }
    seen(mark);
  }
  void OnDocumentEnd() override {}

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    seen(mark);
    take_nodes(1, mark);
    ConfigNode node;
    node.set_where(where(mark));
    remember(anchor, node, 1, 0);
    place(std::move(node), 0, mark);
  }

  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    seen(mark);
    // Escapes in double-quoted scalars ("\0", "\x07", "\uD800") make characters
    // that the check of the text itself cannot see.
    if (const auto problem = find_text_problem(value)) {
      throw ConfigError(where(mark), path_here(),
                        "a character written as an escape is not allowed: " + problem->message);
    }
    take_nodes(1, mark);
    // yaml-cpp tags quoted scalars "!" and plain ones "?".
    ConfigNode node = ConfigNode::scalar(value, where(mark), tag == "!");
    remember(anchor, node, 1, 0);
    place(std::move(node), 0, mark);
  }

  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    seen(mark);
    const auto found = anchors_.find(anchor);
    if (found == anchors_.end()) {
      throw ConfigError(where(mark), path_here(), "alias to an unknown anchor");
    }
    const Anchored& anchored = found->second;
    if (!anchored.complete) {
      throw ConfigError(where(mark), path_here(),
                        "this alias refers to a list or map that contains it");
    }
    check_depth(level_here() + anchored.height - 1, mark);
    take_nodes(anchored.nodes, mark);
    place(ConfigNode(anchored.node), anchored.height, mark);
  }

  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(ConfigNode::sequence(where(mark)), anchor, mark);
  }
  void OnSequenceEnd() override { close(); }

  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(ConfigNode::map(where(mark)), anchor, mark);
  }
  void OnMapEnd() override { close(); }

 private:
  SourceLocation where(const YAML::Mark& mark) const { return location_of(mark, file_); }

  void seen(const YAML::Mark& mark) {
    if (!mark.is_null() && mark.pos >= 0) last_pos_ = static_cast<std::size_t>(mark.pos);
  }

  // The `---` line that starts a second document, when there is one between
  // the first document's last value and `mark`; otherwise `mark` itself.
  SourceLocation second_document_location(const YAML::Mark& mark) const {
    const std::size_t end =
        mark.is_null() || mark.pos < 0 ? text_.size() : static_cast<std::size_t>(mark.pos);
    for (std::size_t at = text_.find("---", last_pos_); at != std::string::npos && at <= end;
         at = text_.find("---", at + 1)) {
      const bool line_start = at == 0 || text_[at - 1] == '\n';
      const bool marker_end =
          at + 3 == text_.size() || std::string(" \t\r\n").find(text_[at + 3]) != std::string::npos;
      if (line_start && marker_end) {
        int line = 1;
        for (std::size_t i = 0; i < at; ++i) line += text_[i] == '\n';
        return SourceLocation{file_, line, 1};
      }
    }
    return where(mark);
  }

  // The key path of the value parsed next.
  std::string path_here() const {
    if (open_.empty()) return "";
    const OpenNode& parent = open_.back();
    if (parent.node.is_sequence()) {
      return parent.path + "[" + std::to_string(parent.node.items().size()) + "]";
    }
    return parent.has_key ? child_path(parent.path, parent.key) : parent.path;
  }

  // The nesting level of a list or map opened next (the root is level 1).
  int level_here() const { return base_depth_ + static_cast<int>(open_.size()) + 1; }

  void check_depth(int level, const YAML::Mark& mark) const {
    if (level > kMaxConfigDepth) {
      throw ConfigError(
          where(mark), path_here(),
          fmt::format("lists and maps nested more than {} levels deep", kMaxConfigDepth));
    }
  }

  void take_nodes(std::size_t nodes, const YAML::Mark& mark) {
    if (nodes > budget_.nodes_left) {
      throw ConfigError(where(mark), path_here(),
                        fmt::format("the config holds more than {} values (counting every alias "
                                    "expansion, include and override)",
                                    kMaxConfigNodes));
    }
    budget_.nodes_left -= nodes;
  }

  void remember(YAML::anchor_t anchor, const ConfigNode& node, std::size_t nodes, int height) {
    if (anchor == YAML::NullAnchor) return;
    anchors_[anchor] = Anchored{node, nodes, height, true};
  }

  void check_not_a_key(const YAML::Mark& mark, const char* what) const {
    if (!open_.empty() && open_.back().node.is_map() && !open_.back().has_key) {
      throw ConfigError(where(mark), open_.back().path,
                        std::string("map keys must be scalars, not ") + what);
    }
  }

  void open(ConfigNode node, YAML::anchor_t anchor, const YAML::Mark& mark) {
    seen(mark);
    check_not_a_key(mark, node.is_map() ? "maps" : "lists");
    check_depth(level_here(), mark);
    OpenNode opened;
    opened.nodes_left_before = budget_.nodes_left;
    take_nodes(1, mark);
    opened.path = path_here();
    opened.node = std::move(node);
    opened.anchor = anchor;
    if (anchor != YAML::NullAnchor) anchors_[anchor] = Anchored{};
    open_.push_back(std::move(opened));
  }

  void close() {
    OpenNode done = std::move(open_.back());
    open_.pop_back();
    if (done.anchor != YAML::NullAnchor) {
      anchors_[done.anchor] =
          Anchored{done.node, done.nodes_left_before - budget_.nodes_left, done.height, true};
    }
    const SourceLocation node_where = done.node.where();
    place(std::move(done.node), done.height, node_where);
  }

  void place(ConfigNode node, int height, const YAML::Mark& mark) {
    place(std::move(node), height, where(mark));
  }

  void place(ConfigNode node, int height, const SourceLocation& here) {
    if (open_.empty()) {
      root_ = std::move(node);
      return;
    }
    OpenNode& parent = open_.back();
    parent.height = std::max(parent.height, height + 1);
    if (parent.node.is_sequence()) {
      parent.node.items().push_back(std::move(node));
      return;
    }
    if (parent.has_key) {
      parent.node.entries().push_back(
          MapEntry{std::move(parent.key), std::move(parent.key_where), std::move(node)});
      parent.has_key = false;
      return;
    }
    if (node.is_null()) throw ConfigError(here, parent.path, "empty map key");
    if (!node.is_scalar()) {
      throw ConfigError(
          here, parent.path,
          std::string("map keys must be scalars, not ") + (node.is_map() ? "maps" : "lists"));
    }
    const std::string& key = node.text();
    if (key == "<<" && !node.quoted()) {
      throw ConfigError(here, child_path(parent.path, key),
                        "YAML merge keys (<<) are not supported: write the keys out, or put "
                        "shared keys in a file named by include:");
    }
    if (!parent.keys.insert(key).second) {
      throw ConfigError(here, child_path(parent.path, key), "duplicate key");
    }
    parent.has_key = true;
    parent.key = key;
    parent.key_where = here;
  }

  const std::string& text_;
  const std::string& file_;
  ConfigBudget& budget_;
  const int base_depth_;
  int documents_ = 0;
  std::size_t last_pos_ = 0;
  ConfigNode root_;
  std::vector<OpenNode> open_;
  std::map<YAML::anchor_t, Anchored> anchors_;
};

}  // namespace

ConfigNode build_yaml_tree(const std::string& text, const std::string& file, ConfigBudget& budget,
                           int base_depth) {
  std::istringstream stream(text);
  TreeBuilder builder(text, file, budget, base_depth);
  try {
    YAML::Parser parser(stream);
    if (!parser.HandleNextDocument(builder)) return builder.take_root();
    // A second document fails in OnDocumentStart.
    parser.HandleNextDocument(builder);
  } catch (const YAML::DeepRecursion& e) {
    throw ConfigError(location_of(e.mark, file), "",
                      fmt::format("YAML nested too deeply (more than {} levels)", kMaxConfigDepth));
  } catch (const YAML::Exception& e) {
    throw ConfigError(location_of(e.mark, file), "", "YAML syntax error: " + e.msg);
  }
  return builder.take_root();
}

}  // namespace corrmp

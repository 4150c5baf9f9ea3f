// Reading a config file's bytes safely: only regular files (not directories,
// devices such as /dev/zero, FIFOs or sockets), at most kMaxConfigFileBytes.
// docs/architecture.md, "Configs".
#pragma once

#include <string>

#include "core/config/config_error.hpp"

namespace corrmp {

// The bytes of the config file at `path`. Errors name `path`; for an included
// file, `included_from` is the location of its name in the including file and
// the error is reported there (key path "include").
std::string read_config_file(const std::string& path,
                             const SourceLocation* included_from = nullptr);

}  // namespace corrmp

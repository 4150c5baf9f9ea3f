// Reading a whole file with errors that name it and say what is wrong (a
// directory, a device or pipe, a missing file, a failing read) instead of the
// stream library's "basic_filebuf::underflow" without a path.
#pragma once

#include <string>

#include "core/file_error.hpp"

namespace corrmp {

// The bytes of the regular file at `path`. Throws FileError with the problem
// "cannot open for reading: <reason>" (a missing file included), "is a
// directory", "is not a regular file (<kind>)" or "read error: <reason>".
// Never blocks on a named pipe.
std::string read_whole_file(const std::string& path);

}  // namespace corrmp

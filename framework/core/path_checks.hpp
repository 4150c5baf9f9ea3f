// Checks on paths a tool is about to write: whether an output is one of its inputs (the same
// file under any spelling or link), and what is in the way of a folder that has to be made.
#pragma once

#include <string>

namespace corrmp {

// Whether `a` and `b` name the same existing file, after symbolic links and whatever the
// spelling ("x", "./x", "d/../x", a link to x). False when either does not exist.
bool same_file(const std::string& a, const std::string& b);

// Why `folder` cannot be made: "'<p>' is a file, not a folder" for the first of it and its
// parents that exists and is not a folder; "" when nothing is in the way.
std::string file_in_the_way(const std::string& folder);

}  // namespace corrmp

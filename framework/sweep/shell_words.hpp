// Words for bash command lines the sweep tools write or print (the Slurm array script,
// docs/slurm.md; the resume command a stopped sweep prints, docs/sweeps.md).
#pragma once

#include <string>

namespace corrmp {

// A word bash takes literally: single quotes, each ' written as '\''.
std::string shell_quoted(const std::string& text);

// The word as is when bash would take it literally anyway (letters, digits and
// _/.,:=+-@%), else shell_quoted: commands a user copies stay readable.
std::string shell_word(const std::string& text);

}  // namespace corrmp

// Suggestions for misspelt config keys and registry names ("did you mean 'width'?").
#pragma once

#include <string>
#include <vector>

namespace corrmp {

// Levenshtein edit distance between two strings.
int edit_distance(const std::string& a, const std::string& b);

// The candidate closest to `word` if it is close enough to be a plausible typo
// (distance at most max(2, size/3)), else an empty string.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" or "" when nothing is close.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace corrmp

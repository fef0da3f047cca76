#pragma once

#include <string>
#include <vector>

namespace lancer {

// " (did you mean "x"?)" for the candidate closest to `word` in edit distance, when it is close
// enough to be a likely misspelling; "" otherwise.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace lancer

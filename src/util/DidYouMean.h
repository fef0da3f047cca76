#pragma once

#include <optional>
#include <string>
#include <vector>

namespace lancer {

// The index of the candidate closest to `word` in edit distance (ignoring case), when it is
// close enough to be a likely misspelling; nothing otherwise.
std::optional<std::size_t> nearestName(const std::string& word,
                                       const std::vector<std::string>& candidates);

// " (did you mean "x"?)" for the nearest candidate (nearestName); "" when there is none.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

// The message for a name that is not one of `valid`: "unknown WHAT "word" (did you mean "x"?);
// expected "a", "b" or "c"".
std::string unknownName(const std::string& what, const std::string& word,
                        const std::vector<std::string>& valid);

}  // namespace lancer

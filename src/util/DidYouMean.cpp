#include "util/DidYouMean.h"

#include <algorithm>
#include <cctype>

#include "util/Registry.h"

namespace lancer {

namespace {

// Levenshtein distance, ignoring case.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            current[j] =
                std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

}  // namespace

std::optional<std::size_t> nearestName(const std::string& word,
                                       const std::vector<std::string>& candidates) {
    std::optional<std::size_t> best;
    std::size_t bestDistance = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const std::size_t d = editDistance(word, candidates[i]);
        if (!best || d < bestDistance) {
            best = i;
            bestDistance = d;
        }
    }
    // Two edits, or a third of the word for long words, still reads as a typo.
    const std::size_t tolerance = std::max<std::size_t>(2, word.size() / 3);
    if (!best || bestDistance > tolerance || bestDistance >= word.size()) return std::nullopt;
    return best;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
    const std::optional<std::size_t> best = nearestName(word, candidates);
    return best ? " (did you mean \"" + candidates[*best] + "\"?)" : "";
}

std::string unknownName(const std::string& what, const std::string& word,
                        const std::vector<std::string>& valid) {
    return "unknown " + what + " \"" + word + "\"" + didYouMean(word, valid) + "; expected " +
           quotedNames(valid);
}

}  // namespace lancer

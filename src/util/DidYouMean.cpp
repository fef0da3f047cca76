#include "util/DidYouMean.h"

#include <algorithm>
#include <cctype>

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

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string* best = nullptr;
    std::size_t bestDistance = 0;
    for (const std::string& candidate : candidates) {
        const std::size_t d = editDistance(word, candidate);
        if (!best || d < bestDistance) {
            best = &candidate;
            bestDistance = d;
        }
    }
    // Two edits, or a third of the word for long words, still reads as a typo.
    const std::size_t tolerance = std::max<std::size_t>(2, word.size() / 3);
    if (!best || bestDistance > tolerance || bestDistance >= word.size()) return "";
    return " (did you mean \"" + *best + "\"?)";
}

}  // namespace lancer

#pragma once

#include <algorithm>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace lancer {

// Names for a message: "\"a\", \"b\" or \"c\"".
inline std::string quotedNames(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) text += i + 1 == names.size() ? " or " : ", ";
        text += "\"" + names[i] + "\"";
    }
    return text;
}

// A table of named entries: the one list of what can be created by name (integrators, filters,
// shapes...), read by the scene loader, the command line and the error messages alike. Entry is
// any struct with a `name` member convertible to std::string_view.
template <typename Entry>
class Registry {
public:
    Registry(std::initializer_list<Entry> entries) : entries_(entries) {}

    // The entry called `name`, or null.
    const Entry* find(std::string_view name) const {
        const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) {
            return std::string_view(e.name) == name;
        });
        return it == entries_.end() ? nullptr : &*it;
    }

    // The names, in the table's order.
    std::vector<std::string> names() const {
        std::vector<std::string> names;
        for (const Entry& e : entries_)
            names.emplace_back(e.name);
        return names;
    }

    // The names for a message: "\"a\", \"b\" or \"c\"".
    std::string quotedNames() const { return lancer::quotedNames(names()); }

    const std::vector<Entry>& entries() const { return entries_; }

private:
    std::vector<Entry> entries_;
};

}  // namespace lancer

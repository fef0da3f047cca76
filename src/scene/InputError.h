#pragma once

#include "scene/SourceLocation.h"

#include <stdexcept>
#include <string>

namespace lancer {

// Bad input from the user (scene, model, texture): reported as one line,
// "file:line:col: error: message", and exit status 2.
class InputError : public std::runtime_error {
public:
    InputError(const std::string& file, const SourceLocation& where, const std::string& message)
        : std::runtime_error(format(file, where, message)), message_(message) {}
    InputError(const std::string& file, const std::string& message)
        : InputError(file, SourceLocation{}, message) {}

    // The message alone, without the file and position.
    const std::string& message() const { return message_; }

private:
    std::string message_;

    static std::string format(const std::string& file, const SourceLocation& where,
                              const std::string& message) {
        std::string prefix = file;
        if (where.line > 0)
            prefix += ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
        return prefix + ": error: " + message;
    }
};

}  // namespace lancer

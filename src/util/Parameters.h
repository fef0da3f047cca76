#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "math/Color.h"
#include "math/Vec3.h"

namespace lancer {

// The keys of one object of the scene file, for the class the object makes (a shape) to read
// itself: each read checks the value and reports a mistake as the scene loader does, one line
// naming the file, line, column and key, so that a class never sees the file format.
class Parameters {
public:
    virtual ~Parameters() = default;

    virtual bool has(const std::string& key) const = 0;
    // Required values: a missing key is an error too.
    virtual float number(const std::string& key) const = 0;
    // A number greater than `minimum` (at least `minimum` when inclusive).
    virtual float numberAbove(const std::string& key, float minimum, bool inclusive) const = 0;
    virtual Vec3 point(const std::string& key) const = 0;
    // A non-zero vector, not normalised.
    virtual Vec3 direction(const std::string& key) const = 0;
    virtual Color color(const std::string& key) const = 0;
    virtual bool flag(const std::string& key) const = 0;
    // One of `options` (a string), as its index.
    virtual std::size_t choice(const std::string& key,
                               const std::vector<std::string>& options) const = 0;
    // The keys of the object that is the key's value, which must have only the given keys.
    virtual std::unique_ptr<Parameters> object(const std::string& key,
                                               const std::vector<std::string>& keys) const = 0;
    // An error at the key's value (or at the object, for a key it does not have).
    [[noreturn]] virtual void fail(const std::string& key, const std::string& message) const = 0;
};

}  // namespace lancer

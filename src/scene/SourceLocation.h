#pragma once

namespace lancer {

// Where in a text file something stands; line and column count from 1 (0: unknown).
struct SourceLocation {
    int line = 0;
    int column = 0;
};

}  // namespace lancer

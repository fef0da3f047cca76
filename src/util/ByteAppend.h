#pragma once

#include <string>

namespace lancer {

// Appends a fixed-size value's bytes, in the machine's byte order, to the bytes of a binary file
// that lancer writes (a resume file, a model cache entry): what ByteReader::read reads back.
template <typename T>
void appendBytes(std::string& bytes, const T& value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

}  // namespace lancer

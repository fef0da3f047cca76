#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <string_view>

namespace lancer {

// Reads fixed-size values, in the machine's byte order, from the bytes of a binary file that
// lancer wrote (a radiosity solution, a resume file), checking every length against what is left:
// a damaged file is an error, never a read past its end.
class ByteReader {
public:
    // `fail(what)` throws the caller's error for a file that "is truncated" and so on; it must
    // not return.
    ByteReader(std::string_view bytes, std::function<void(const std::string& what)> fail)
        : bytes_(bytes), fail_(std::move(fail)) {}

    template <typename T>
    T read() {
        T value;
        need(sizeof(T));
        std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
        offset_ += sizeof(T);
        return value;
    }
    float readFinite() {
        const auto v = read<float>();
        if (!std::isfinite(v)) fail("holds a value that is not a finite number");
        return v;
    }
    // A count of records of `recordSize` bytes that must fit in what is left of the file.
    std::uint64_t readCount(std::size_t recordSize) {
        const auto count = read<std::uint64_t>();
        if (count > (bytes_.size() - offset_) / recordSize) fail("is truncated");
        return count;
    }
    // The next n bytes, as they are.
    std::string_view readBytes(std::size_t n) {
        need(n);
        const std::string_view bytes = bytes_.substr(offset_, n);
        offset_ += n;
        return bytes;
    }
    bool atEnd() const { return offset_ == bytes_.size(); }
    [[noreturn]] void fail(const std::string& what) const {
        fail_(what);
        std::abort();  // fail_ broke its promise to throw
    }

private:
    void need(std::size_t n) const {
        if (bytes_.size() - offset_ < n) fail("is truncated");
    }

    std::string_view bytes_;
    std::function<void(const std::string&)> fail_;
    std::size_t offset_ = 0;
};

}  // namespace lancer

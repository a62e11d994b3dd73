// The messages of a cluster run between rank 0 (the coordinator) and the other ranks. Every
// process of the job runs the same program on the same machine type, so numbers travel as raw
// bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace rt::cluster {

enum Tag : int {
    kHello = 1,    ///< rank -> 0: what it renders (scene, switches, window), checked against 0's
    kRequest = 2,  ///< rank -> 0: more rows, please
    kWork = 3,     ///< 0 -> rank: rows [first, first + count) counted from the window's bottom;
                   ///< count 0: there are no more
    kStop = 4,     ///< 0 -> rank: stop now (another rank failed); answer with kDone
    kRow = 5,      ///< rank -> 0: a finished row: y, its samples, its pixels
    kDone = 6,     ///< rank -> 0: finished (its last message): the unrepresentable samples and
                   ///< the rays it traced by kind (KindCounters), for -p
    kFailed = 7,   ///< rank -> 0: failed (its last message): the error message
};

/// Appends and reads plain values as bytes.
class Packer {
public:
    template <typename T>
    Packer& put(const T& value) {
        return append(&value, sizeof(T));
    }
    template <typename T>
    Packer& put_all(std::span<const T> values) {
        return append(values.data(), values.size_bytes());
    }
    Packer& put_text(const std::string& text) { return append(text.data(), text.size()); }
    std::vector<std::byte> bytes;

private:
    // resize and memcpy rather than insert, which GCC 12 warns about falsely
    // (-Wstringop-overflow).
    Packer& append(const void* data, std::size_t size) {
        const std::size_t at = bytes.size();
        bytes.resize(at + size);
        if (size > 0) {
            std::memcpy(bytes.data() + at, data, size);
        }
        return *this;
    }
};

class Unpacker {
public:
    explicit Unpacker(std::span<const std::byte> bytes) : bytes_(bytes) {}
    /// False if fewer than sizeof(T) bytes are left (value untouched).
    template <typename T>
    bool get(T& value) {
        if (bytes_.size() - at_ < sizeof(T)) {
            return false;
        }
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return true;
    }
    std::span<const std::byte> rest() const { return bytes_.subspan(at_); }
    std::string rest_as_text() const {
        return {reinterpret_cast<const char*>(rest().data()), rest().size()};
    }

private:
    std::span<const std::byte> bytes_;
    std::size_t at_ = 0;
};

}  // namespace rt::cluster

// Byte-level helpers shared by the binary scene's writer and reader: fixed
// little-endian numbers whatever the host, and the section alignment.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace orb::detail {

inline constexpr std::size_t kBinaryPreambleSize = 16;  // magic, version, header length
inline constexpr std::size_t kBinaryArrayAlignment = 8;   // the float64 arrays start on 8 bytes

inline std::size_t binary_padding(std::size_t offset) {
    return (kBinaryArrayAlignment - offset % kBinaryArrayAlignment) % kBinaryArrayAlignment;
}

template <typename T>
T from_little_endian(const char* bytes) {
    T value;
    if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(&value, bytes, sizeof(T));
    } else {
        char swapped[sizeof(T)];
        for (std::size_t i = 0; i < sizeof(T); ++i) swapped[i] = bytes[sizeof(T) - 1 - i];
        std::memcpy(&value, swapped, sizeof(T));
    }
    return value;
}

template <typename T>
void append_little_endian(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native != std::endian::little)
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    out.append(bytes, sizeof(T));
}

}  // namespace orb::detail

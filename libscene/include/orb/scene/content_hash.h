// 64-bit FNV-1a, written as 16 hex digits: how Orb names the content of a
// scene (orb:sceneHash) and of a colour config (a display image's record).
// It tells a change of content, not an adversary's collision.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace orb {

class ContentHash {
public:
    void add(std::string_view bytes) {
        for (unsigned char byte : bytes) add_byte(byte);
    }
    void add_uint32(std::uint32_t value) {  // little-endian
        for (int shift = 0; shift < 32; shift += 8) add_byte(static_cast<unsigned char>(value >> shift));
    }
    std::string hex() const;

private:
    void add_byte(unsigned char byte) {
        hash_ ^= byte;
        hash_ *= 1099511628211ull;  // FNV-1a 64-bit prime
    }
    std::uint64_t hash_ = 1469598103934665603ull;  // FNV-1a 64-bit offset basis
};

// The hash of `bytes` alone.
std::string content_hash_hex(std::string_view bytes);

}  // namespace orb

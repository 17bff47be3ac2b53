#include "orb/denoise/exr_memory_streams.h"

#include <Iex.h>

#include <cstring>

namespace orb::denoise {

bool MemoryInput::read(char c[], int n) {
    if (n < 0 || position_ > bytes_.size() || bytes_.size() - position_ < static_cast<uint64_t>(n))
        throw Iex::InputExc("unexpected end of file");
    std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
    position_ += static_cast<uint64_t>(n);
    return position_ < bytes_.size();
}

void MemoryOutput::write(const char c[], int n) {
    // OpenEXR seeks back to fill in the offset table, so writes may land inside.
    const std::size_t end = static_cast<std::size_t>(position_) + static_cast<std::size_t>(n);
    if (bytes_.size() < end) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
    position_ = end;
}

}  // namespace orb::denoise

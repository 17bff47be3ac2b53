#include "frame_plan.h"

namespace orb::render_cli {
namespace {

// SplitMix64's output function (Steele, Lea, Flood 2014): a bijection of
// 64-bit words that mixes every input bit into every output bit.
std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

}  // namespace

double frame_time(long frame, double fps) { return static_cast<double>(frame) / fps; }

std::uint64_t frame_seed(std::uint64_t seed, long frame) {
    return mix64(seed ^ mix64(static_cast<std::uint64_t>(frame) + 1));
}

}  // namespace orb::render_cli

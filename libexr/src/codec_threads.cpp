#include "orb/exr/codec_threads.h"

#include <OpenEXR/ImfThreading.h>

#include <thread>

namespace orb::exr {

int use_all_cores_for_codecs() {
    static const int threads = [] {
        const unsigned cores = std::thread::hardware_concurrency();
        const int count = cores > 1 ? static_cast<int>(cores) : 0;
        Imf::setGlobalThreadCount(count);
        return count;
    }();
    return threads;
}

}  // namespace orb::exr

#include "orb/image/source_identity.h"

#include <OpenImageIO/imageio.h>
#include <sys/stat.h>

#include <cerrno>
#include <fstream>
#include <memory>

namespace OIIO = OIIO_NAMESPACE;

namespace orb::image {
namespace {

bool starts_like_exr(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    return in.read(magic, 4) && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

// The header's orb-render attributes; none when the file is not an EXR or its
// header does not read (then tonemapping it reports the problem).
std::vector<std::pair<std::string, std::string>> render_attributes(const std::string& path) {
    std::vector<std::pair<std::string, std::string>> out;
    if (!starts_like_exr(path)) return out;
    auto in = OIIO::ImageInput::open(path);  // reads the header only
    if (!in) {
        (void)OIIO::geterror();  // not ours to report: clear it
        return out;
    }
    const OIIO::ImageSpec& spec = in->spec();
    for (const std::string& name : render_identity_attributes())
        if (const OIIO::ParamValue* value = spec.find_attribute(name)) out.emplace_back(name, value->get_string());
    in->close();
    return out;
}

}  // namespace

const std::vector<std::string>& render_identity_attributes() {
    static const std::vector<std::string> names = {
        "orb:sceneHash", "orb:sceneTime", "orb:spp", "orb:sampleRanges", "orb:seed", "orb:mode", "orb:maxDepth",
    };
    return names;
}

SourceLookup identify_source(const std::string& path) {
    SourceLookup lookup;
    if (path == "-") return lookup;
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        lookup.state =
            errno == ENOENT || errno == ENOTDIR ? SourceLookup::State::Missing : SourceLookup::State::NotAFile;
        return lookup;
    }
    if (!S_ISREG(st.st_mode)) return lookup;
    lookup.state = SourceLookup::State::File;
    lookup.identity.size = static_cast<std::uint64_t>(st.st_size);
    lookup.identity.mtime_ns =
        static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + static_cast<std::int64_t>(st.st_mtim.tv_nsec);
    lookup.identity.render = render_attributes(path);
    return lookup;
}

}  // namespace orb::image

#include "orb/cli/output_overlap.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "dangling_links.h"
#include "orb/cli/tool_main.h"

namespace orb::cli {
namespace {

namespace fs = std::filesystem;

// What makes two names one file: device and inode when it exists, else the
// normalised absolute path it would be created at.
struct Identity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::string future_path;

    bool operator==(const Identity& other) const {
        if (exists != other.exists) return false;
        return exists ? device == other.device && inode == other.inode : future_path == other.future_path;
    }
};

std::optional<Identity> identity_of(const std::string& path, bool as_output) {
    if (path.empty() || path == "-") return std::nullopt;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        // Devices and FIFOs are streamed into, not replaced: nothing to destroy.
        if (as_output && !S_ISREG(st.st_mode)) return std::nullopt;
        return Identity{true, st.st_dev, st.st_ino, {}};
    }
    if (!as_output) return std::nullopt;  // a missing input is reported when it is read
    std::error_code ec;
    const fs::path target = fs::weakly_canonical(fs::absolute(detail::follow_dangling_links(path), ec), ec);
    return Identity{false, 0, 0, target.lexically_normal().string()};
}

bool is_allowed(const std::vector<std::pair<std::string, std::string>>& allowed, const std::string& input_option,
                const std::string& output_option) {
    return std::find(allowed.begin(), allowed.end(), std::make_pair(input_option, output_option)) != allowed.end();
}

}  // namespace

void refuse_overlapping_paths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs,
                              const std::vector<std::pair<std::string, std::string>>& allowed) {
    std::vector<std::optional<Identity>> output_ids;
    for (const NamedPath& out : outputs) output_ids.push_back(identity_of(out.path, true));

    for (std::size_t o = 0; o < outputs.size(); ++o) {
        if (!output_ids[o]) continue;
        for (const NamedPath& in : inputs) {
            const std::optional<Identity> input_id = identity_of(in.path, false);
            if (!input_id || !(*input_id == *output_ids[o]) || is_allowed(allowed, in.option, outputs[o].option))
                continue;
            throw UsageError(outputs[o].option + " " + outputs[o].path + " is the input " + in.option + " " +
                             in.path + " (the same file); refusing to overwrite an input");
        }
        for (std::size_t other = 0; other < o; ++other) {
            if (output_ids[other] && *output_ids[other] == *output_ids[o])
                throw UsageError(outputs[other].option + " " + outputs[other].path + " and " + outputs[o].option +
                                 " " + outputs[o].path + " are the same file; give each output its own name");
        }
    }
}

}  // namespace orb::cli

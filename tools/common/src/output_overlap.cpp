#include "orb/cli/output_overlap.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <tuple>

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

    auto key() const { return std::tie(exists, device, inode, future_path); }
    bool operator<(const Identity& other) const { return key() < other.key(); }
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

// "--config ocio.config" for an option's value, "the input scene.json" for an argument.
std::string describe_input(const NamedPath& in) {
    return (in.option.starts_with('-') ? in.option : std::string("the input")) + " " + in.path;
}

bool is_allowed(const std::vector<std::pair<std::string, std::string>>& allowed, const std::string& input_option,
                const std::string& output_option) {
    return std::find(allowed.begin(), allowed.end(), std::make_pair(input_option, output_option)) != allowed.end();
}

}  // namespace

void refuse_overlapping_paths(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs,
                              const std::vector<std::pair<std::string, std::string>>& allowed) {
    // Each path is looked at once: a sequence of thousands of frames must
    // not cost thousands of stat() calls per frame.
    std::multimap<Identity, const NamedPath*> input_files;  // in input order within one file
    for (const NamedPath& in : inputs)
        if (const std::optional<Identity> id = identity_of(in.path, false)) input_files.emplace(*id, &in);
    std::map<Identity, const NamedPath*> earlier_outputs;

    for (const NamedPath& out : outputs) {
        const std::optional<Identity> id = identity_of(out.path, true);
        if (!id) continue;
        const auto [first, last] = input_files.equal_range(*id);
        for (auto it = first; it != last; ++it) {
            const NamedPath& in = *it->second;
            if (is_allowed(allowed, in.option, out.option)) continue;
            throw UsageError(out.option + " " + out.path + " is " + describe_input(in) +
                             " (the same file); refusing to overwrite an input");
        }
        const auto [earlier, is_new] = earlier_outputs.emplace(*id, &out);
        if (!is_new)
            throw UsageError(earlier->second->option + " " + earlier->second->path + " and " + out.option + " " +
                             out.path + " are the same file; give each output its own name");
    }
}

}  // namespace orb::cli

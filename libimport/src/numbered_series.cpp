#include "orb/import/numbered_series.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "orb/scene/error.h"

namespace orb {
namespace fs = std::filesystem;

namespace {

// The name of the file at `number`, zero-padded as `neighbour`'s number is (frame.0007.xyz), for messages.
std::string name_at(const std::string& prefix, std::uint64_t number, const std::string& suffix,
                    const std::string& neighbour_path) {
    const std::size_t width = neighbour_path.size() - prefix.size() - suffix.size();
    std::string digits = std::to_string(number);
    if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
    return prefix + digits + suffix;
}

bool all_digits(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

bool is_series_pattern(const std::string& path) {
    if (path.find('*') == std::string::npos) return false;
    std::error_code ec;
    return !fs::exists(path, ec);
}

std::vector<SeriesFile> find_numbered_series(const std::string& pattern) {
    const std::size_t slash = pattern.rfind('/');
    const std::string folder = slash == std::string::npos ? "" : pattern.substr(0, slash + 1);
    const std::string name = pattern.substr(folder.size());
    const std::size_t star = name.find('*');
    if (folder.find('*') != std::string::npos)
        throw InputError(pattern + ": the * of a numbered series stands for the number in the file name; "
                                   "the folder cannot have one");
    if (star == std::string::npos || name.find('*', star + 1) != std::string::npos)
        throw InputError(pattern + ": a numbered series has one * where the frame number is (frame.*.xyz)");
    const std::string prefix = name.substr(0, star), suffix = name.substr(star + 1);

    std::vector<SeriesFile> files;
    std::error_code ec;
    const fs::path listed = folder.empty() ? fs::path(".") : fs::path(folder);
    fs::directory_iterator entries(listed, ec);
    if (ec) throw InputError(pattern + ": cannot list the folder " + listed.string() + ": " + ec.message());
    for (const fs::directory_entry& entry : entries) {
        const std::string file = entry.path().filename().string();
        if (file.size() < prefix.size() + suffix.size() || !file.starts_with(prefix) || !file.ends_with(suffix))
            continue;
        std::error_code type_error;
        if (entry.is_directory(type_error)) continue;
        const std::string middle = file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
        if (!all_digits(middle))
            throw InputError(pattern + ": " + folder + file + " matches the pattern but has no number where the * is" +
                             (middle.empty() ? "" : " ('" + middle + "')") +
                             "; move it away, or name the series more closely");
        if (middle.size() > 18) throw InputError(pattern + ": " + folder + file + ": the number is too long to read");
        files.push_back({folder + file, std::stoull(middle)});
    }
    if (files.empty())
        throw InputError(pattern + ": no file matches (a numbered series: " + (prefix + "0" + suffix) + ", " +
                         (prefix + "1" + suffix) + ", ... in " + (folder.empty() ? "this folder" : folder) + ")");
    std::sort(files.begin(), files.end(), [](const SeriesFile& a, const SeriesFile& b) {
        return a.number != b.number ? a.number < b.number : a.path < b.path;
    });
    for (std::size_t i = 1; i < files.size(); ++i)
        if (files[i].number == files[i - 1].number)
            throw InputError(pattern + ": " + files[i - 1].path + " and " + files[i].path +
                             " have the same number; keep one of them");
    // The numbers step evenly (every frame, or every 100th timestep): the smallest step is the series' step.
    std::uint64_t step = 0;
    for (std::size_t i = 1; i < files.size(); ++i) {
        const std::uint64_t gap = files[i].number - files[i - 1].number;
        if (step == 0 || gap < step) step = gap;
    }
    for (std::size_t i = 1; i < files.size(); ++i) {
        const std::uint64_t gap = files[i].number - files[i - 1].number;
        if (gap == step) continue;
        if (gap % step == 0)
            throw InputError(pattern + ": " + name_at(folder + prefix, files[i - 1].number + step, suffix, files[i - 1].path) +
                             " is missing: the series steps by " + std::to_string(step) + ", and " +
                             files[i - 1].path + " is followed by " + files[i].path);
        throw InputError(pattern + ": the numbers do not step evenly: " + files[i - 1].path + " is followed by " +
                         files[i].path + ", " + std::to_string(gap) + " on, where the smallest step is " +
                         std::to_string(step));
    }
    return files;
}

}  // namespace orb

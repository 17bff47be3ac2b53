#include "format_list.h"

#include <algorithm>
#include <vector>

#include "orb/import/importers.h"

namespace orb::import_tool {
namespace {

std::string joined(const std::vector<std::string_view>& words, const char* separator) {
    std::string text;
    for (std::string_view word : words) {
        if (!text.empty()) text += separator;
        text += word;
    }
    return text;
}

}  // namespace

std::string format_list() {
    struct Row {
        std::string format, files, options, description;
    };
    std::vector<Row> rows{{"FORMAT", "FILES", "OPTIONS", "DESCRIPTION"}};
    for (const SceneImporter& importer : scene_importers()) {
        std::vector<std::string_view> words{importer.name};
        words.insert(words.end(), importer.aliases.begin(), importer.aliases.end());
        rows.push_back({joined(words, ", "), joined(importer.extensions, " "),
                        importer.options ? std::string(importer.options->heading) : "-",
                        std::string(importer.description)});
    }
    std::size_t format_width = 0, files_width = 0, options_width = 0;
    for (const Row& row : rows) {
        format_width = std::max(format_width, row.format.size());
        files_width = std::max(files_width, row.files.size());
        options_width = std::max(options_width, row.options.size());
    }
    std::string text;
    for (const Row& row : rows) {
        text += row.format + std::string(format_width + 2 - row.format.size(), ' ');
        text += row.files + std::string(files_width + 2 - row.files.size(), ' ');
        text += row.options + std::string(options_width + 2 - row.options.size(), ' ');
        text += row.description + "\n";
    }
    return text;
}

}  // namespace orb::import_tool

#include "keyword_options.h"

#include <pybind11/pybind11.h>

#include <algorithm>

namespace orb::python {

void parse_keyword_options(CLI::App& app, const KeywordOptions& options, const std::string& function) {
    std::vector<std::string> words;
    for (const auto& [name, value] : options) {
        std::string option = "--" + name;
        std::replace(option.begin(), option.end(), '_', '-');
        const CLI::Option* declared = app.get_option_no_throw(option);
        if (declared == nullptr || declared->get_group().empty())  // unlisted: kept for scripts only
            throw pybind11::type_error(function + "() got an unexpected keyword argument '" + name + "'");
        words.push_back(value ? option + "=" + *value : option);
    }
    std::reverse(words.begin(), words.end());  // CLI11 takes a vector of arguments last first
    app.parse(words);
}

}  // namespace orb::python

#include "program_source.h"

#include <fstream>
#include <span>
#include <sstream>
#include <stdexcept>

#include "orb/kernels/embedded.h"
#include "orb/tables/kernel_features.h"

namespace orb::render {
namespace {

std::string read_text_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read kernel file " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The files in program order, from `dir` or embedded.
std::string concatenated(std::span<const kernels::EmbeddedKernel> files, const std::string& dir)
{
    std::string source;
    for (const kernels::EmbeddedKernel& kernel : files) {
        const std::string name(kernel.file_name);
        // #line keeps build-log positions pointing into the right file.
        source += "#line 1 \"" + name + "\"\n";
        source += dir.empty() ? std::string(kernel.source) : read_text_file(dir + "/" + name);
        source += "\n";
    }
    return source;
}

}  // namespace

std::string program_source(const std::string& dir)
{
    // The kernels' defaults come first, generated from the one table of
    // kernel_features.h (the preprocessor cannot expand a table into
    // #define lines), so every file may read every feature.
    return "#line 1 \"kernel feature defaults\"\n" + device::kernel_feature_defaults() +
           concatenated(kernels::embedded_kernels(), dir);
}

std::string decision_program_source(const std::string& dir)
{
    return concatenated(kernels::embedded_decision_kernels(), dir);
}

}  // namespace orb::render

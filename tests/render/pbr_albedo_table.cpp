#include "pbr_albedo_table.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "orb/kernels/embedded.h"

namespace orb::render::test {
namespace {

// The numbers between the braces that follow `name` in `text`.
std::vector<double> array_after(const std::string& text, const std::string& name)
{
    std::size_t at = text.find(name);
    if (at == std::string::npos) throw std::runtime_error("bsdf_pbr_albedo.cl has no " + name);
    at = text.find('{', at);
    const std::size_t end = text.find('}', at);
    std::vector<double> values;
    const char* p = text.c_str() + at + 1;
    const char* stop = text.c_str() + end;
    while (p < stop) {
        char* next = nullptr;
        const double v = std::strtod(p, &next);
        if (next == p) {
            ++p;
            continue;
        }
        values.push_back(v);
        p = next;
    }
    return values;
}

double number_after(const std::string& text, const std::string& label)
{
    const std::size_t at = text.find(label);
    if (at == std::string::npos) throw std::runtime_error("bsdf_pbr_albedo.cl has no \"" + label + "\"");
    return std::strtod(text.c_str() + at + label.size(), nullptr);
}

}  // namespace

double PbrAlbedoTable::interpolate(double cos_o, double roughness) const
{
    const double last = size - 1;
    const double x = std::clamp(cos_o, 0.0, 1.0) * last;
    const double y = std::clamp((roughness - min_roughness) / (1.0 - min_roughness), 0.0, 1.0) * last;
    const int i = std::min(static_cast<int>(x), size - 2), j = std::min(static_cast<int>(y), size - 2);
    const double fx = x - i, fy = y - j;
    const auto at = [&](int a, int b) { return table[static_cast<std::size_t>(b * size + a)]; };
    const double lower = at(i, j) + (at(i + 1, j) - at(i, j)) * fx;
    const double upper = at(i, j + 1) + (at(i + 1, j + 1) - at(i, j + 1)) * fx;
    return lower + (upper - lower) * fy;
}

const PbrAlbedoTable& pbr_albedo_table()
{
    static const PbrAlbedoTable table = [] {
        const std::string text(kernels::find_embedded_kernel("bsdf_pbr_albedo.cl"));
        PbrAlbedoTable t;
        t.size = static_cast<int>(number_after(text, "#define PBR_ALBEDO_SIZE "));
        t.min_roughness = number_after(text, "#define PBR_ALBEDO_MIN_ROUGHNESS ");
        t.largest_raise = number_after(text, "largest raise ");
        t.table = array_after(text, "pbr_albedo_table[");
        t.average = array_after(text, "pbr_albedo_average[");
        if (t.table.size() != static_cast<std::size_t>(t.size * t.size) || t.average.size() != static_cast<std::size_t>(t.size))
            throw std::runtime_error("bsdf_pbr_albedo.cl: unexpected table sizes");
        return t;
    }();
    return table;
}

}  // namespace orb::render::test

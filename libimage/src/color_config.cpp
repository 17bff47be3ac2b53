#include "orb/image/color_config.h"

#include "orb/scene/content_hash.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "color_config_impl.h"
#include "orb/scene/error.h"

namespace orb::image {
namespace {

std::string file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(path + ": cannot read the OpenColorIO config");
    return text;
}

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& s : items) out += (out.empty() ? "" : ", ") + ("'" + s + "'");
    return out;
}

}  // namespace

ColorConfig ColorConfig::load(const std::string& explicit_path, const std::string& default_path) {
    std::string path = explicit_path;
    std::string origin = "--config";
    if (path.empty()) {
        const char* env = std::getenv("OCIO");
        if (env && *env) {
            path = env;
            origin = "$OCIO";
        } else {
            path = default_path;
            origin = "Orb's default config";
        }
    }
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw InputError(path + ": OpenColorIO config not found (from " + origin + ")");
    auto impl = std::make_shared<Impl>();
    try {
        impl->config = OCIO::Config::CreateFromFile(path.c_str());
        impl->config->validate();
    } catch (const OCIO::Exception& e) {
        throw InputError(path + ": invalid OpenColorIO config: " + e.what());
    }
    ColorConfig result;
    result.impl_ = impl;
    result.source_ = path;
    result.content_hash_ = orb::content_hash_hex(file_text(path));
    return result;
}

std::vector<std::string> ColorConfig::displays() const {
    std::vector<std::string> out;
    for (int i = 0; i < impl_->config->getNumDisplays(); ++i) out.emplace_back(impl_->config->getDisplay(i));
    return out;
}

std::vector<std::string> ColorConfig::views(const std::string& display) const {
    std::vector<std::string> out;
    for (int i = 0; i < impl_->config->getNumViews(display.c_str()); ++i)
        out.emplace_back(impl_->config->getView(display.c_str(), i));
    return out;
}

std::vector<std::string> ColorConfig::looks() const {
    std::vector<std::string> out;
    for (int i = 0; i < impl_->config->getNumLooks(); ++i) out.emplace_back(impl_->config->getLookNameByIndex(i));
    return out;
}

std::vector<std::string> ColorConfig::color_spaces() const {
    std::vector<std::string> out;
    const auto& c = impl_->config;
    for (int i = 0; i < c->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL); ++i)
        out.emplace_back(c->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i));
    return out;
}

std::string ColorConfig::default_display() const { return impl_->config->getDefaultDisplay(); }

std::string ColorConfig::default_view(const std::string& display) const {
    return impl_->config->getDefaultView(display.c_str());
}

std::string ColorConfig::resolve_color_space(const std::string& name) const {
    if (name.empty()) return {};
    auto cs = impl_->config->getColorSpace(name.c_str());  // also resolves roles and aliases
    return cs ? std::string(cs->getName()) : std::string();
}

std::string ColorConfig::scene_linear() const {
    for (const char* role : {OCIO::ROLE_SCENE_LINEAR, OCIO::ROLE_DEFAULT, OCIO::ROLE_REFERENCE}) {
        std::string resolved = resolve_color_space(role);
        if (!resolved.empty()) return resolved;
    }
    throw InputError(source_ + ": the config defines no scene_linear role; pass --input-space");
}

std::array<double, 3> ColorConfig::luma_coefficients() const {
    std::array<double, 3> rgb{};
    impl_->config->getDefaultLumaCoefs(rgb.data());
    return rgb;
}

std::string ColorConfig::encoded_input_space(const std::string& file_tag) const {
    for (const std::string& candidate : {file_tag, std::string("sRGB - Texture"), std::string("sRGB"),
                                         std::string("srgb_tx"), std::string("Utility - sRGB - Texture")}) {
        std::string resolved = resolve_color_space(candidate);
        if (!resolved.empty()) return resolved;
    }
    throw InputError(source_ + ": no sRGB colour space to read 8/16-bit images with; pass --input-space");
}

void ColorConfig::check_display_view(const std::string& display, const std::string& view) const {
    const auto all = displays();
    if (std::find(all.begin(), all.end(), display) == all.end())
        throw InputError("unknown display '" + display + "' in " + source_ + " (displays: " + join(all) + ")");
    const auto v = views(display);
    if (std::find(v.begin(), v.end(), view) == v.end())
        throw InputError("display '" + display + "' has no view '" + view + "' in " + source_ +
                         " (views: " + join(v) + ")");
}

void ColorConfig::check_look(const std::string& look) const {
    if (look.empty()) return;
    // A look override may list several looks separated by commas, with +/- prefixes.
    std::stringstream items(look);
    std::string item;
    while (std::getline(items, item, ',')) {
        while (!item.empty() && (item.front() == ' ' || item.front() == '+' || item.front() == '-')) item.erase(0, 1);
        while (!item.empty() && item.back() == ' ') item.pop_back();
        if (!impl_->config->getLook(item.c_str()))
            throw InputError("unknown look '" + item + "' in " + source_ + " (looks: " + join(looks()) + ")");
    }
}

std::string ColorConfig::listing() const {
    std::ostringstream out;
    out << "config: " << source_ << "\n";
    out << "displays (default " << default_display() << "):\n";
    for (const std::string& d : displays()) {
        out << "  " << d << "\n";
        for (const std::string& v : views(d))
            out << "    " << v << (v == default_view(d) ? "  (default)" : "") << "\n";
    }
    out << "looks:\n";
    for (const std::string& l : looks()) out << "  " << l << "\n";
    out << "color spaces:\n";
    for (const std::string& cs : color_spaces()) {
        auto space = impl_->config->getColorSpace(cs.c_str());
        const bool display = space && space->getReferenceSpaceType() == OCIO::REFERENCE_SPACE_DISPLAY;
        out << "  " << cs << (display ? "  [display]" : "") << "\n";
    }
    out << "roles:\n";
    for (int i = 0; i < impl_->config->getNumRoles(); ++i)
        out << "  " << impl_->config->getRoleName(i) << ": " << impl_->config->getRoleColorSpace(i) << "\n";
    return out.str();
}

}  // namespace orb::image

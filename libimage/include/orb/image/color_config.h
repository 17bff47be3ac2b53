// The OpenColorIO config a tool works with: --config FILE, else $OCIO, else
// Orb's own config in share/orb/ocio. Hides OCIO types from the tools.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace orb::image {

class ColorConfig {
public:
    // `explicit_path` (from --config) wins over $OCIO, which wins over
    // `default_path`. Throws orb::InputError if the config cannot be loaded.
    static ColorConfig load(const std::string& explicit_path, const std::string& default_path);

    const std::string& source() const { return source_; }  // where it came from, for messages
    // The config's identity by content, not by path: the 64-bit FNV-1a of the
    // config file's text as 16 hex digits. Files the config refers to (LUTs)
    // and the environment its context variables read are not part of it.
    const std::string& content_hash() const { return content_hash_; }

    std::vector<std::string> displays() const;
    std::vector<std::string> views(const std::string& display) const;
    std::vector<std::string> looks() const;
    std::vector<std::string> color_spaces() const;
    std::string default_display() const;
    std::string default_view(const std::string& display) const;

    // Canonical name of a colour space, role or alias; empty if unknown.
    std::string resolve_color_space(const std::string& name) const;
    // The weights of R, G, B in luminance Y for the scene_linear space (the
    // config's luma coefficients; Rec. 709's 0.2126, 0.7152, 0.0722 in Orb's).
    std::array<double, 3> luma_coefficients() const;

    // The scene_linear role (or the default role) resolved to a colour space.
    std::string scene_linear() const;
    // Best guess for 8/16-bit display-encoded files: their tag, else an sRGB space.
    std::string encoded_input_space(const std::string& file_tag) const;

    // Throws orb::cli-style usage problems as orb::InputError with the valid choices listed.
    void check_display_view(const std::string& display, const std::string& view) const;
    void check_look(const std::string& look) const;

    // Human-readable listing for --list.
    std::string listing() const;

    struct Impl;
    const Impl& impl() const { return *impl_; }

private:
    std::shared_ptr<const Impl> impl_;
    std::string source_;
    std::string content_hash_;
};

}  // namespace orb::image

// Recognising a scene file by content and importing it into the canonical
// model. The formats are the entries of orb/import/importers.h.
#pragma once

#include <any>
#include <map>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include "orb/scene/scene.h"

namespace orb {

// Each importer's own options, one struct per importer (GltfImportOptions,
// PlyImportOptions, MolecularImportOptions, in their headers), held by type:
// a format with options adds its struct in its own header and nothing here.
class FormatOptions {
public:
    // The options of type T, made with T's defaults when first asked for.
    // The reference stays valid while this object lives (the tools bind
    // command-line options to the members).
    template <typename T>
    T& get() {
        std::any& held = options_[std::type_index(typeid(T))];
        if (!held.has_value()) held.emplace<T>();
        return std::any_cast<T&>(held);
    }
    // The options of type T as set, or T's defaults when none were.
    template <typename T>
    const T& get() const {
        const auto found = options_.find(std::type_index(typeid(T)));
        if (found != options_.end()) return std::any_cast<const T&>(found->second);
        static const T defaults{};
        return defaults;
    }

private:
    std::map<std::type_index, std::any> options_;  // a map: its elements never move
};

struct ImportOptions {
    // A name of an importer (orb/import/importers.h: "ply", "json", ...);
    // empty: recognise the format by content (and the name's extension).
    std::string format;
    // A scene without spheres is refused, with what was left out and why
    // (an asset of triangle meshes); true accepts it.
    bool allow_empty = false;
    // Each format's options: options.of<PlyImportOptions>().radius.
    FormatOptions formats;
    template <typename T>
    T& of() { return formats.get<T>(); }
    template <typename T>
    const T& of() const { return formats.get<T>(); }
};

struct ImportResult {
    Scene scene;
    std::vector<std::string> warnings;  // losses: an error for tools run with --strict
    std::vector<std::string> notices;   // additions, such as glTF's default light: warned about, never fatal
    std::string_view format;            // the name of the importer that read it ("gltf")
};

// `source` names the input in messages (a path, or <stdin>); without a chosen
// format its extension helps to choose one: a .gltf/.glb/.ply/.orb name goes
// to that reader even when the content is too broken to recognise, and a
// format Orb does not read (tri.obj, by content or by name) is refused as
// such. `base_dir` resolves external files (glTF buffers). Throws InputError,
// also for a `format` no importer has.
ImportResult import_scene(std::string_view bytes, const std::string& source, const std::string& base_dir,
                          const ImportOptions& options = {});

// Frame options.of<MolecularImportOptions>().frame of a numbered series of molecular files
// ("dump.*.lammpstrj", orb/import/molecular.h open_molecular_series), as
// import_scene reads one of a single file. Throws InputError, also when
// options.format is given and the series is another format.
ImportResult import_molecular_series(const std::string& pattern, const ImportOptions& options = {});

}  // namespace orb

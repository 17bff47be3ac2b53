// orb-import: any scene Orb can read (the importers of orb/scene/importers.h:
// Orb JSON, SmallptGPU .scn, glTF, GLB, PLY, ...) -> the canonical Orb JSON
// scene, its binary form (.orb), or back to .scn (docs/orb-import.md).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "environment_options.h"
#include "format_list.h"
#include "gltf_options.h"
#include "map_paths.h"
#include "orb/cli/camera_options.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/molecule_options.h"
#include "orb/cli/output_file.h"
#include "orb/cli/legend_output.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/sphere_style_options.h"
#include "orb/cli/tool_main.h"
#include "orb/cli/texture_decoder_loader.h"
#include "orb/scene/error.h"
#include "orb/scene/import.h"
#include "orb/scene/importers.h"
#include "orb/scene/numbered_series.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "orb/scene/scn.h"
#include "output_format.h"
#include "ply_options.h"

namespace {

constexpr const char* kDescription =
    "Convert a scene (Orb JSON, SmallptGPU .scn, glTF 2.0 .gltf/.glb, PLY point cloud, PDB/mmCIF, XYZ, LAMMPS\n"
    "dump, GROMACS .gro: --list-formats) to the\n"
    "canonical Orb JSON scene, the binary Orb scene (.orb, for millions of spheres), or back to SmallptGPU .scn.\n"
    "The input format is recognised by content.";

constexpr const char* kExamples = R"(Examples:
  orb-import scenes/cornell.scn -o cornell.json      .scn -> Orb JSON
  orb-import model.glb > model.json                  glTF binary -> Orb JSON on stdout
  orb-import cloud.ply --radius 0.01 -o cloud.json   PLY point cloud -> spheres, camera, lights
  orb-import cloud.ply -o cloud.orb                  ... -> the binary scene (fast to load)
  orb-import cloud.orb -o cloud.json                 binary scene -> Orb JSON, exactly
  orb-import md.ply --color-by temperature --colormap inferno -o md.orb   colour by a vertex property
  orb-import 4hhb.pdb -o 4hhb.json                   protein: an atom per sphere, coloured by element
  orb-import traj.lammpstrj --frame 10 --cell -o f10.orb   frame 10 of a LAMMPS dump, with its box
  orb-import model.glb --environment sky.exr -o m.json  lit by an HDR map (or --environment R,G,B)
  orb-import cornell.json --to scn -o cornell.scn    Orb JSON -> .scn (warns about losses)
  orb-import scan.orb --look-at 0,0.1,0 --vfov 30 -o scan-closer.orb   move the camera of a binary scene
  orb-import model.gltf --to scn --strict -o m.scn   fail instead of losing anything
  cat scene.txt | orb-import - --from scn            read stdin, say what it is
  orb-import cornell.scn | orb-render - -o - | orb-tonemap - -o cornell.png
  orb-import --list-formats                          the formats Orb reads, their files and options

Orb reads no other format: an OBJ, STL, FBX, ... input is refused as such.
A scene that ends with no sphere (a glTF asset of triangle meshes) is an error
naming what was left out and why, unless --allow-empty.

Exit status: 0 success, 1 bad input or failed job (no output file is left behind),
2 usage error. Details: docs/orb-import.md)";

struct Arguments {
    std::string input;
    std::string output = "-";
    std::string from;
    std::string to;
    bool strict = false;
    bool list_formats = false;
    orb::ImportOptions import_options;
    orb::import_tool::EnvironmentChoice environment;
    orb::cli::CameraOptions camera;
    orb::cli::SphereStyleArguments style;
};

// Where relative references (glTF buffers and images, environment maps) are
// resolved from: a file's folder, the current directory for stdin/stdout.
std::string base_directory(const std::string& input) {
    if (orb::cli::is_stdio(input)) return std::filesystem::current_path().string();
    const std::filesystem::path parent = std::filesystem::path(input).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

// Warnings, or with --strict one error naming them all (and no output).
void report_losses(const std::vector<std::string>& losses, bool strict, const std::string& what) {
    if (losses.empty()) return;
    if (strict) {
        std::string message = what + " would lose information (--strict):";
        for (const auto& loss : losses) message += "\n  " + loss;
        throw orb::InputError(message);
    }
    for (const auto& loss : losses) orb::cli::warning(loss);
}

// Options of one format given for an input of another are named, not silently dropped.
void warn_about_other_formats_options(const CLI::App& app, std::string_view format, const std::string& source) {
    const std::string given = orb::import_tool::options_for_other_formats(app, format);
    if (!given.empty())
        orb::cli::warning(source + ": ignored " + given + ": the input is read as " + std::string(format) +
                          " (orb-import --list-formats says which options each format takes)");
}

int run(Arguments& args, const CLI::App& app) {
    using orb::import_tool::OutputFormat;
    using orb::import_tool::rebase_environment_map;
    if (args.list_formats) return orb::cli::print_to_stdout(orb::import_tool::format_list());
    if (args.input.empty()) throw orb::cli::UsageError("missing INPUT (a scene file, or - for stdin)");
    const orb::SphereStyleOptions style = orb::cli::sphere_style_options(args.style);
    const OutputFormat to = orb::import_tool::choose_output_format(args.to, args.output);
    // Without --from, the content (and the name's extension) says the format (orb::import_scene).
    args.import_options.format = args.from;
    args.import_options.gltf.strict = args.strict;
    args.import_options.gltf.image_decoder = orb::cli::texture_decoder();  // glTF textures, through OpenImageIO, loaded when needed
    // A chosen environment lights the scene: no default light for a glTF asset.
    if (!args.environment.value.empty()) args.import_options.gltf.default_light = false;

    // The output is checked and prepared before anything is read or converted.
    orb::cli::refuse_overlapping_paths({{"INPUT", args.input}}, {{"-o", args.output}});
    orb::cli::OutputFile output(args.output, "-o");
    std::optional<orb::cli::LegendOutput> legend =
        orb::cli::LegendOutput::prepare(args.style, {{"INPUT", args.input}, {"-o", args.output}});
    // Checked before the input is read, which may be millions of spheres.
    std::optional<orb::Environment> environment =
        orb::import_tool::chosen_environment(args.environment, base_directory(args.output));

    const std::string source = orb::cli::is_stdio(args.input) ? "<stdin>" : args.input;
    // A numbered series ("frame.*.xyz") is one trajectory of its files' frames.
    const bool series = !orb::cli::is_stdio(args.input) && orb::is_series_pattern(args.input);
    const std::string bytes = series ? std::string() : orb::cli::read_input(args.input);
    orb::ImportResult imported =
        series ? orb::import_molecular_series(args.input, args.import_options)
               : orb::import_scene(bytes, source, base_directory(args.input), args.import_options);
    warn_about_other_formats_options(app, imported.format, source);
    report_losses(imported.warnings, args.strict, source);
    for (const std::string& notice : imported.notices) orb::cli::warning(notice);  // additions lose nothing: never fatal
    rebase_environment_map(imported.scene, base_directory(args.input), base_directory(args.output));
    if (environment) imported.scene.environment = std::move(*environment);
    // Styling sizes spheres, which the automatic camera may then frame.
    const orb::SphereStyleResult styled = orb::cli::apply_sphere_style(imported.scene, style, source);
    // The command line's camera wins over the file's (or the automatic one).
    orb::cli::apply_camera_options(args.camera, imported.scene, imported.scene.render.width,
                                   imported.scene.render.height, source);
    if (imported.scene.animation.camera_node >= 0 &&
        (args.camera.position || args.camera.look_at || args.camera.up || args.camera.auto_camera))
        orb::cli::warning(source + ": the camera is animated, and each pose replaces its position, look-at and up: "
                          "--camera-position, --look-at, --up and --auto-camera set only its rest pose; give them to orb-render, "
                          "which applies them to every pose");

    std::string text;
    if (to == OutputFormat::Scn) {
        orb::ScnWriteResult written = orb::write_scn(imported.scene);
        report_losses(written.lossy, args.strict, "writing .scn");
        text = std::move(written.text);
    } else if (to == OutputFormat::OrbBinary) {
        text = orb::write_scene_binary(imported.scene);
    } else {
        text = orb::write_scene_json(imported.scene);
    }
    output.write(text);
    if (legend) legend->write(styled, source);
    return orb::cli::kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
    Arguments args;
    const CLI::App* parsed = nullptr;
    return orb::cli::run_tool(
        argc, argv, "orb-import", kDescription,
        [&](CLI::App& app) {
            parsed = &app;
            app.add_option("INPUT", args.input, "Scene to read; - reads stdin");
            app.add_option("-o,--output", args.output, "Where to write; - (the default) writes stdout")
                ->option_text("FILE");
            const std::vector<std::string> formats = orb::scene_format_words();
            std::string format_choice;
            for (const std::string& word : formats) {
                if (!format_choice.empty()) format_choice += '|';
                format_choice += word;
            }
            app.add_option("--from", args.from, "Input format, instead of recognising it by content (--list-formats)")
                ->check(CLI::IsMember(formats))
                ->option_text(format_choice);
            app.add_flag("--list-formats", args.list_formats,
                         "List the input formats: their names, files, options and what they hold; then exit");
            app.add_option("--to", args.to,
                           "Output format: orb (Orb JSON), orb-binary or scn; default from the -o extension (.orb: "
                           "orb-binary, .scn), else orb")
                ->check(CLI::IsMember({"orb", "json", "scn", "orb-binary"}))
                ->option_text("orb|orb-binary|scn");
            app.add_flag("--strict", args.strict,
                         "Fail (exit 1, no output) instead of warning when information would be lost");
            app.add_flag("--allow-empty", args.import_options.allow_empty,
                         "Write a scene without spheres instead of failing (a glTF asset of triangle meshes)");
            orb::import_tool::add_gltf_options(app, args.import_options.gltf);
            orb::import_tool::add_ply_options(app, args.import_options.ply);
            orb::cli::add_molecule_options(app, args.import_options.molecular, true);
            orb::import_tool::add_environment_options(app, args.environment);
            orb::cli::add_camera_options(app, args.camera);
            orb::cli::add_sphere_style_options(app, args.style);
            app.footer(kExamples);
        },
        [&] { return run(args, *parsed); });
}

// orb-import: any scene Orb can read (the importers of orb/import/importers.h:
// Orb JSON, SmallptGPU .scn, glTF, GLB, PLY, ...) -> the canonical Orb JSON
// scene, its binary form (.orb), or back to .scn (docs/orb-import.md).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "format_list.h"
#include "orb/cli/camera_options.h"
#include "orb/cli/io.h"
#include "orb/cli/legend_output.h"
#include "orb/cli/map_paths.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_file.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/scene_reading.h"
#include "orb/cli/sphere_style_options.h"
#include "orb/cli/tool_main.h"
#include "orb/scene/error.h"
#include "orb/import/gltf.h"
#include "orb/import/import.h"
#include "orb/import/importers.h"
#include "orb/import/molecular.h"
#include "orb/import/numbered_series.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "orb/import/scn.h"
#include "output_format.h"

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
    orb::cli::SceneReading reading;  // every importer's options, --environment
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

int run(Arguments& args) {
    using orb::cli::rebase_environment_map;
    using orb::import_tool::OutputFormat;
    if (args.list_formats) return orb::cli::print_to_stdout(orb::import_tool::format_list());
    if (args.input.empty()) throw orb::cli::UsageError("missing INPUT (a scene file, or - for stdin)");
    const orb::SphereStyleOptions style = orb::cli::sphere_style_options(args.style);
    const OutputFormat to = orb::import_tool::choose_output_format(args.to, args.output);
    orb::ImportOptions import_options = orb::cli::import_options_for(args.reading);
    // Without --from, the content (and the name's extension) says the format (orb::import_scene).
    import_options.format = args.from;
    import_options.of<orb::GltfImportOptions>().strict = args.strict;

    // The output is checked and prepared before anything is read or converted.
    orb::cli::refuse_overlapping_paths({{"INPUT", args.input}}, {{"-o", args.output}});
    orb::cli::OutputFile output(args.output, "-o");
    std::optional<orb::cli::LegendOutput> legend =
        orb::cli::LegendOutput::prepare(args.style, {{"INPUT", args.input}, {"-o", args.output}});
    // Checked before the input is read, which may be millions of spheres.
    std::optional<orb::Environment> environment =
        orb::cli::chosen_environment(args.reading.environment, base_directory(args.output));

    const std::string source = orb::cli::is_stdio(args.input) ? "<stdin>" : args.input;
    // A numbered series ("frame.*.xyz") is one trajectory of its files' frames.
    const bool series = !orb::cli::is_stdio(args.input) && orb::is_series_pattern(args.input);
    const std::string bytes = series ? std::string() : orb::cli::read_input(args.input);
    orb::ImportResult imported =
        series ? orb::import_molecular_series(args.input, import_options)
               : orb::import_scene(bytes, source, base_directory(args.input), import_options);
    orb::cli::warn_about_other_formats_options(args.reading, imported.format, source);
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
    return orb::cli::run_tool(
        argc, argv, "orb-import", kDescription,
        [&](CLI::App& app) {
            app.add_option("INPUT", args.input, "Scene to read; - reads stdin");
            app.add_option("-o,--output", args.output, "Where to write; - (the default) writes stdout")
                ->option_text("FILE");
            const std::vector<std::string> formats = orb::scene_format_words();
            std::string format_words;  // too many to show as a placeholder within 80 columns
            for (const std::string& word : formats) format_words += (format_words.empty() ? "" : ", ") + word;
            app.add_option("--from", args.from,
                           "Input format, instead of recognising it by content, one of: " + format_words +
                               " (--list-formats)")
                ->check(CLI::IsMember(formats))
                ->option_text("FORMAT");
            app.add_flag("--list-formats", args.list_formats,
                         "List the input formats: their names, files, options and what they hold; then exit");
            app.add_option("--to", args.to,
                           "Output format: orb (Orb JSON), orb-binary or scn; default from the -o extension (.orb: "
                           "orb-binary, .scn), else orb")
                ->check(CLI::IsMember({"orb", "json", "scn", "orb-binary"}))
                ->option_text("orb|orb-binary|scn");
            app.add_flag("--strict", args.strict,
                         "Fail (exit 1, no output) instead of warning when information would be lost");
            app.add_flag("--allow-empty", args.reading.import.allow_empty,
                         "Write a scene without spheres instead of failing (a glTF asset of triangle meshes)");
            orb::cli::add_scene_reading_options(app, args.reading);
            // orb-import writes one frame of a trajectory; orb-render's --frame N renders the same one.
            // Named, like the group's own options, when the input is of another format.
            const std::string_view molecules = orb::find_scene_importer("xyz")->options->heading;
            args.reading.importer_options.push_back(
                {app.add_option("--frame", args.reading.import.of<orb::MolecularImportOptions>().frame,
                                "Which frame of a trajectory or model of an ensemble to write (1 = the first, the "
                                "default)")
                     ->check(CLI::PositiveNumber)
                     ->option_text("N")
                     ->group(std::string(molecules)),
                 molecules});
            // The older name of --gltf-scene, kept for scripts (unlisted: orb-frames' --scene is the scene file).
            app.add_option("--scene", args.reading.import.of<orb::GltfImportOptions>().scene)->group("");
            orb::cli::add_camera_options(app, args.camera);
            orb::cli::add_sphere_style_options(app, args.style);
            app.footer(kExamples);
        },
        [&] { return run(args); });
}

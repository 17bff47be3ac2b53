// The frame sources of orb/import/molecular.h: text trajectories indexed by
// the byte offset of each frame, and the formats read frame by frame as the
// importer registry lists them (orb/import/importers.h open_frames).
#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <optional>

#include "atoms_scene.h"
#include "importer_entries.h"
#include "line_reader.h"
#include "orb/import/import.h"
#include "orb/import/importers.h"
#include "orb/import/molecular.h"
#include "orb/import/numbered_series.h"
#include "orb/scene/error.h"
#include "text_start.h"
#include "text_trajectory.h"

namespace orb {
namespace molecular {
namespace {

// Where a frame starts: its file (of a numbered series), its byte offset and
// the number of its first line (for messages).
struct FrameStart {
    std::uint32_t file = 0;
    std::uint64_t offset = 0;
    std::uint64_t line = 1;
};

// The frames of one text file, or of the files of a numbered series one
// after another (each file's frames in order, then the next file's).
class TextTrajectory final : public FrameSource {
public:
    // `paths` given: frames are read from those files; else from `bytes`.
    // `source` names the whole in messages that are not about one file's line.
    TextTrajectory(const TextFormat& format, std::vector<std::string> paths, std::string_view bytes,
                   std::string source, const MolecularImportOptions& options)
        : format_(format), paths_(std::move(paths)), bytes_(bytes), source_(std::move(source)), options_(options) {
        const std::size_t files = paths_.empty() ? 1 : paths_.size();
        for (std::size_t file = 0; file < files; ++file) {
            std::unique_ptr<LineReader> lines = paths_.empty() ? std::make_unique<LineReader>(bytes_)
                                                               : std::make_unique<LineReader>(paths_[file]);
            const std::size_t before = starts_.size();
            for (;;) {
                const FrameStart start{static_cast<std::uint32_t>(file), lines->next_offset(), lines->line_number() + 1};
                if (!format_.skip_frame(*lines, name_of(file))) break;
                starts_.push_back(start);
            }
            ends_.push_back(lines->next_offset());
            if (starts_.size() == before && files > 1)
                throw InputError(name_of(file) + ": no frames (the file holds no atoms), in the series " + source_);
        }
        if (starts_.empty()) throw InputError(source_ + ": no frames (the file holds no atoms)");
        AtomFrame first = read(0);
        warnings_ = std::move(first.warnings);
        first_ = atoms_scene(std::move(first), options_, view_, source_);
        ++built_;
    }

    std::size_t frame_count() const override { return starts_.size(); }

    Scene frame(std::size_t index) const override {
        if (index >= starts_.size())
            throw InputError(source_ + ": has " + std::to_string(starts_.size()) + " frames; no frame " + std::to_string(index + 1));
        if (index == 0) {
            // Frame 1 was read to fix the view: handed out once rather than read again.
            std::lock_guard<std::mutex> lock(first_mutex_);
            if (first_) {
                Scene scene = std::move(*first_);
                first_.reset();
                return scene;
            }
        }
        AtomFrame frame = read(index);
        FrameView view = view_;
        ++built_;
        return atoms_scene(std::move(frame), options_, view, source_);
    }

    const std::vector<std::string>& warnings() const override { return warnings_; }
    std::string_view format() const override { return format_.name; }
    std::size_t frames_built() const override { return built_.load(); }

private:
    const std::string& name_of(std::size_t file) const { return paths_.empty() ? source_ : paths_[file]; }

    AtomFrame read(std::size_t index) const {
        const FrameStart& start = starts_[index];
        const bool last_of_file = index + 1 == starts_.size() || starts_[index + 1].file != start.file;
        const std::uint64_t end = last_of_file ? ends_[start.file] : starts_[index + 1].offset;
        std::string held;
        std::string_view bytes;
        if (paths_.empty()) {
            bytes = bytes_.substr(start.offset, end - start.offset);
        } else {
            held = read_file_range(paths_[start.file], start.offset, end);
            bytes = held;
        }
        LineReader lines(bytes, start.line, start.offset);
        return format_.read_frame(lines, name_of(start.file));
    }

    const TextFormat& format_;
    std::vector<std::string> paths_;
    std::string_view bytes_;
    std::string source_;
    MolecularImportOptions options_;
    std::vector<FrameStart> starts_;
    std::vector<std::uint64_t> ends_;  // where each file's last frame ends
    FrameView view_;
    std::vector<std::string> warnings_;
    mutable std::mutex first_mutex_;
    mutable std::optional<Scene> first_;  // frame 1 as read for the view, until it is asked for
    mutable std::atomic<std::size_t> built_{0};
};

}  // namespace

std::unique_ptr<FrameSource> open_text_trajectory(const TextFormat& format, const FrameInput& input,
                                                  const MolecularImportOptions& options) {
    return std::make_unique<TextTrajectory>(format, input.paths, input.bytes, input.source, options);
}

}  // namespace molecular

namespace {

// The importer of frames `format` names, or an InputError for `source`.
const SceneImporter& frame_importer(std::string_view format, const std::string& source) {
    const SceneImporter* importer = find_frame_importer(format);
    if (!importer) throw InputError(source + ": not a molecular format: " + std::string(format));
    return *importer;
}

// Frame `frame` (from 1) of a molecular file or series, with what reading it lost and how many frames there are.
ImporterOutput molecular_frame(const FrameSource& frames, const std::string& source, long frame) {
    const std::size_t count = frames.frame_count();
    if (frame < 1 || static_cast<std::size_t>(frame) > count)
        throw InputError(source + ": has " + std::to_string(count) + (count == 1 ? " frame" : " frames") +
                         " (1-" + std::to_string(count) + "); there is no frame " + std::to_string(frame));
    ImporterOutput output = detail::scene_only(frames.frame(static_cast<std::size_t>(frame - 1)));
    validate_scene(output.imported.scene, source);  // the rules every scene obeys, whoever built it
    output.imported.warnings = frames.warnings();
    if (count > 1)
        output.imported.notices.push_back(source + ": holds " + std::to_string(count) + " frames; this is frame " +
                                          std::to_string(frame) + " (orb-render --frames 1-" + std::to_string(count) +
                                          " renders them all from the file)");
    return output;
}

}  // namespace

// orb-import writes one frame of a molecular file (--frame, the first by
// default); orb-render reads them frame by frame from the file instead
// (orb/request/scene_input.h).
ImporterOutput detail::read_chosen_frame(const SceneImporter& importer, std::string_view bytes,
                                         const std::string& source, const ImportOptions& options) {
    const MolecularImportOptions& molecular = options.of<MolecularImportOptions>();
    const std::unique_ptr<FrameSource> frames = importer.open_frames(FrameInput{{}, bytes, source}, molecular);
    return molecular_frame(*frames, source, molecular.frame);
}

std::string_view recognise_molecular_file(std::string_view head, const std::string& path) {
    (void)path;
    for (const SceneImporter& importer : scene_importers())
        if (importer.open_frames && importer.recognise(head) == ContentMatch::Yes) return importer.name;
    return {};
}

std::unique_ptr<FrameSource> open_molecular_bytes(std::string_view bytes, const std::string& source,
                                                  std::string_view format, const MolecularImportOptions& options) {
    return frame_importer(format, source).open_frames(FrameInput{{}, bytes, source}, options);
}

std::unique_ptr<FrameSource> open_molecular_file(const std::string& path, std::string_view format,
                                                 const MolecularImportOptions& options) {
    return frame_importer(format, path).open_frames(FrameInput{{path}, {}, path}, options);
}

std::string_view molecular_file_format(const std::string& path) {
    // The start of the file tells (a few kilobytes), else its name (.gro has no signature to speak of).
    const std::string head = molecular::read_file_head(path, detail::kRecognisedHead);
    std::string_view format = recognise_molecular_file(head, path);
    if (!format.empty()) return format;
    const SceneImporter* named = scene_importer_for_path(path);
    if (!named || !named->open_frames) return {};
    // A name that decides, unless the content is another importer's.
    if (const SceneImporter* recognised = recognise_scene(head); recognised && recognised != named) return {};
    return named->name;
}

std::unique_ptr<FrameSource> open_molecular_series(const std::string& pattern, const MolecularImportOptions& options) {
    const std::vector<SeriesFile> files = find_numbered_series(pattern);
    const std::string_view format = molecular_file_format(files.front().path);
    if (format.empty())
        throw InputError(pattern + ": " + files.front().path +
                         " is not a molecular or particle trajectory (XYZ, LAMMPS dump, .gro)");
    const SceneImporter& importer = frame_importer(format, pattern);
    if (!importer.reads_series)
        throw InputError(pattern + ": a numbered series of " + std::string(format) +
                         " files is not read (a series is of XYZ, LAMMPS dump or .gro files); render each file alone");
    std::vector<std::string> paths;
    for (const SeriesFile& file : files) {
        const std::string_view other = molecular_file_format(file.path);
        if (other != format)
            throw InputError(pattern + ": mixed formats: " + files.front().path + " is " + std::string(format) + ", " +
                             file.path + " is " + (other.empty() ? std::string("no molecular format") : std::string(other)) +
                             "; a series is of one format");
        paths.push_back(file.path);
    }
    return importer.open_frames(FrameInput{std::move(paths), {}, pattern}, options);
}

ImportResult import_molecular_series(const std::string& pattern, const ImportOptions& options) {
    const MolecularImportOptions& molecular = options.of<MolecularImportOptions>();
    const std::unique_ptr<FrameSource> frames = open_molecular_series(pattern, molecular);
    if (!options.format.empty()) {  // --from: the importer's name or an alias ("lammpstrj")
        const SceneImporter* chosen = find_scene_importer(options.format);
        if (!chosen || chosen->name != frames->format())
            throw InputError(pattern + ": --from " + options.format + ", but the series is " +
                             std::string(frames->format()));
    }
    ImportResult result = molecular_frame(*frames, pattern, molecular.frame).imported;
    result.format = frames->format();
    return result;
}

}  // namespace orb

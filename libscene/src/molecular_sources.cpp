// The frame sources of orb/scene/molecular.h: text trajectories indexed by
// the byte offset of each frame, and the recognising of the formats.
#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <optional>

#include "atoms_scene.h"
#include "import_option_groups.h"
#include "line_reader.h"
#include "orb/scene/error.h"
#include "orb/scene/importers.h"
#include "orb/scene/molecular.h"
#include "orb/scene/numbered_series.h"
#include "structure_source.h"
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

const TextFormat* text_format(std::string_view name) {
    for (const TextFormat* format : {&xyz_format(), &lammps_dump_format(), &gro_format()})
        if (format->name == name) return format;
    return nullptr;
}

std::string_view first_line(std::string_view text) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

// Up to `count` lines from the start.
std::vector<std::string_view> head_lines(std::string_view text, std::size_t count) {
    std::vector<std::string_view> lines;
    while (lines.size() < count && !text.empty()) {
        lines.push_back(first_line(text));
        const std::size_t next = text.find('\n');
        if (next == std::string_view::npos) break;
        text.remove_prefix(next + 1);
    }
    return lines;
}

bool is_count(std::string_view word) {
    return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The Protein Data Bank's record names (wwPDB format 3.3) a file starts with.
bool is_pdb_record(std::string_view line) {
    for (std::string_view record : {"HEADER", "OBSLTE", "TITLE ", "SPLIT ", "CAVEAT", "COMPND", "SOURCE", "KEYWDS",
                                    "EXPDTA", "NUMMDL", "MDLTYP", "AUTHOR", "REVDAT", "SPRSDE", "JRNL  ", "REMARK",
                                    "DBREF ", "SEQRES", "CRYST1", "ORIGX1", "SCALE1", "ATOM  ", "HETATM", "MODEL "})
        if (line.starts_with(record)) return true;
    return false;
}

}  // namespace
}  // namespace molecular

std::string_view recognise_molecular_file(std::string_view head, const std::string& path) {
    using namespace molecular;
    const std::string_view text = detail::skip_bom_and_space(head);
    if (text.empty()) return {};
    const std::string_view line = first_line(text);
    if (line.starts_with("ITEM:")) return "lammps-dump";
    if (is_pdb_record(line)) return "pdb";
    if (line.starts_with("data_")) return "mmcif";
    // XYZ: a count alone on the first line (extra words are tolerated), then the comment line.
    const std::vector<std::string_view> lines = head_lines(text, 3);
    const std::vector<std::string_view> count = split_fields(line);
    if (!count.empty() && count.size() <= 2 && is_count(count[0]) && lines.size() >= 2) {
        if (lines.size() < 3) return "xyz";
        const std::vector<std::string_view> atom = split_fields(lines[2]);
        double number = 0;
        if (atom.size() >= 4 && std::isalnum(static_cast<unsigned char>(atom[0].front())) &&
            parse_double(atom[1], number) && parse_double(atom[2], number) && parse_double(atom[3], number))
            return "xyz";
    }
    // .gro: a title, a count alone, then fixed-column atoms with decimal points at the coordinates' places.
    if (lines.size() >= 3) {
        const std::vector<std::string_view> second = split_fields(lines[1]);
        if (second.size() == 1 && is_count(second[0]) && lines[2].size() >= 44 && lines[2][24] == '.' &&
            lines[2][32] == '.' && lines[2][40] == '.')
            return "gro";
    }
    (void)path;
    return {};
}

std::unique_ptr<FrameSource> open_molecular_bytes(std::string_view bytes, const std::string& source,
                                                  std::string_view format, const MolecularImportOptions& options) {
    using namespace molecular;
    if (const TextFormat* text = text_format(format))
        return std::make_unique<TextTrajectory>(*text, std::vector<std::string>{}, bytes, source, options);
    if (format == "pdb" || format == "mmcif") return open_structure(bytes, source, format, options);
    throw InputError(source + ": not a molecular format: " + std::string(format));
}

std::unique_ptr<FrameSource> open_molecular_file(const std::string& path, std::string_view format,
                                                 const MolecularImportOptions& options) {
    using namespace molecular;
    if (const TextFormat* text = text_format(format))
        return std::make_unique<TextTrajectory>(*text, std::vector<std::string>{path}, std::string_view{}, path, options);
    // PDB and mmCIF files are read whole by gemmi (they are small: a structure, an NMR ensemble).
    const std::string bytes = read_file_range(path, 0, 0);
    return open_structure(bytes, path, format, options);  // gemmi's Structure keeps what it needs
}

std::string_view molecular_file_format(const std::string& path) {
    // The start of the file tells (a few kilobytes), else its name (.gro has no signature to speak of).
    const std::string head = molecular::read_file_head(path, 65536);
    std::string_view format = recognise_molecular_file(head, path);
    if (!format.empty()) return format;
    const SceneImporter* named = scene_importer_for_path(path);
    if (!named || named->options != &detail::kMolecularOptions) return {};
    // A name that decides, unless the content is another importer's.
    if (const SceneImporter* recognised = recognise_scene(head); recognised && recognised != named) return {};
    return named->name;
}

std::unique_ptr<FrameSource> open_molecular_series(const std::string& pattern, const MolecularImportOptions& options) {
    using namespace molecular;
    const std::vector<SeriesFile> files = find_numbered_series(pattern);
    const std::string_view format = molecular_file_format(files.front().path);
    if (format.empty())
        throw InputError(pattern + ": " + files.front().path +
                         " is not a molecular or particle trajectory (XYZ, LAMMPS dump, .gro)");
    const TextFormat* text = text_format(format);
    if (!text)
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
    return std::make_unique<TextTrajectory>(*text, std::move(paths), std::string_view{}, pattern, options);
}

}  // namespace orb

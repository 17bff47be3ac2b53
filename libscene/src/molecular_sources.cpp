// The frame sources of orb/scene/molecular.h: text trajectories indexed by
// the byte offset of each frame, and the recognising of the formats.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "atoms_scene.h"
#include "line_reader.h"
#include "orb/scene/error.h"
#include "orb/scene/molecular.h"
#include "structure_source.h"
#include "text_start.h"
#include "text_trajectory.h"

namespace orb {
namespace molecular {
namespace {

// Where a frame starts: its byte offset and the number of its first line (for messages).
struct FrameStart {
    std::uint64_t offset = 0;
    std::uint64_t line = 1;
};

class TextTrajectory final : public FrameSource {
public:
    // `path` set: frames are read from the file; else from `bytes`.
    TextTrajectory(const TextFormat& format, std::string path, std::string_view bytes, std::string source,
                   const MolecularImportOptions& options)
        : format_(format), path_(std::move(path)), bytes_(bytes), source_(std::move(source)), options_(options) {
        {
            std::unique_ptr<LineReader> lines = path_.empty() ? std::make_unique<LineReader>(bytes_)
                                                              : std::make_unique<LineReader>(path_);
            for (;;) {
                const FrameStart start{lines->next_offset(), lines->line_number() + 1};
                if (!format_.skip_frame(*lines, source_)) break;
                starts_.push_back(start);
            }
            end_ = lines->next_offset();
        }
        if (starts_.empty()) throw InputError(source_ + ": no frames (the file holds no atoms)");
        AtomFrame first = read(0);
        warnings_ = std::move(first.warnings);
        atoms_scene(std::move(first), options_, view_, source_);
    }

    std::size_t frame_count() const override { return starts_.size(); }

    Scene frame(std::size_t index) const override {
        if (index >= starts_.size())
            throw InputError(source_ + ": has " + std::to_string(starts_.size()) + " frames; no frame " + std::to_string(index + 1));
        AtomFrame frame = read(index);
        FrameView view = view_;
        return atoms_scene(std::move(frame), options_, view, source_);
    }

    const std::vector<std::string>& warnings() const override { return warnings_; }
    std::string_view format() const override { return format_.name; }

private:
    AtomFrame read(std::size_t index) const {
        const FrameStart& start = starts_[index];
        const std::uint64_t end = index + 1 < starts_.size() ? starts_[index + 1].offset : end_;
        std::string held;
        std::string_view bytes;
        if (path_.empty()) {
            bytes = bytes_.substr(start.offset, end - start.offset);
        } else {
            held = read_file_range(path_, start.offset, end);
            bytes = held;
        }
        LineReader lines(bytes, start.line, start.offset);
        return format_.read_frame(lines, source_);
    }

    const TextFormat& format_;
    std::string path_;
    std::string_view bytes_;
    std::string source_;
    MolecularImportOptions options_;
    std::vector<FrameStart> starts_;
    std::uint64_t end_ = 0;
    FrameView view_;
    std::vector<std::string> warnings_;
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
        return std::make_unique<TextTrajectory>(*text, "", bytes, source, options);
    if (format == "pdb" || format == "mmcif") return open_structure(bytes, source, format, options);
    throw InputError(source + ": not a molecular format: " + std::string(format));
}

std::unique_ptr<FrameSource> open_molecular_file(const std::string& path, std::string_view format,
                                                 const MolecularImportOptions& options) {
    using namespace molecular;
    if (const TextFormat* text = text_format(format))
        return std::make_unique<TextTrajectory>(*text, path, std::string_view{}, path, options);
    // PDB and mmCIF files are read whole by gemmi (they are small: a structure, an NMR ensemble).
    const std::string bytes = read_file_range(path, 0, 0);
    return open_structure(bytes, path, format, options);  // gemmi's Structure keeps what it needs
}

}  // namespace orb

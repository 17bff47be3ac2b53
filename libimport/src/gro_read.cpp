// GROMACS .gro frames (the GROMACS manual's "gro" file format): a title
// line, the atom count, one fixed-column line per atom (residue number and
// name, atom name and number, position in nm, perhaps velocity in nm/ps) and
// the box line. Lengths are turned into angstrom (x10), the element table's unit.
#include <algorithm>
#include <cctype>

#include "orb/scene/error.h"
#include "importer_entries.h"
#include "text_start.h"
#include "text_trajectory.h"

namespace orb::molecular {
namespace {

constexpr double kAngstromPerNm = 10.0;

bool blank(std::string_view line) { return line.find_first_not_of(" \t\r") == std::string_view::npos; }

std::string_view trimmed(std::string_view text) {
    const std::size_t start = text.find_first_not_of(" \t");
    if (start == std::string_view::npos) return {};
    const std::size_t end = text.find_last_not_of(" \t");
    return text.substr(start, end - start + 1);
}

std::size_t parse_gro_atom_count(std::string_view line, const std::string& source, std::uint64_t number) {
    const std::vector<std::string_view> fields = split_fields(line);
    long long count = -1;
    if (fields.size() != 1 || !parse_long(fields[0], count) || count < 0 || count > 2'000'000'000LL)
        fail_at(source, number, "expected the number of atoms (the second line of a .gro frame), got " + quoted_excerpt(line));
    return static_cast<std::size_t>(count);
}

// Reads the title and count lines; false when only blank lines are left.
bool read_start(LineReader& lines, const std::string& source, std::size_t& count) {
    std::string_view title, line;
    if (!lines.next(title)) return false;
    const bool blank_title = blank(title);
    if (!lines.next(line)) {
        if (blank_title) return false;
        fail_at(source, lines.line_number() + 1, "expected the number of atoms, found the end of the file");
    }
    if (blank_title && blank(line) && lines.only_blank_left()) return false;
    count = parse_gro_atom_count(line, source, lines.line_number());
    return true;
}

bool skip_gro_frame(LineReader& lines, const std::string& source) {
    std::size_t count = 0;
    if (!read_start(lines, source, count)) return false;
    const std::uint64_t count_line = lines.line_number();
    const std::uint64_t got = lines.skip(count + 1);
    if (got < count + 1)
        fail_at(source, count_line,
                "the frame announces " + std::to_string(count) + " atoms and a box line, but the file ends " +
                    std::to_string(got) + " lines later (truncated?)");
    return true;
}

// The element an atom name shows: an ion whose atom and residue names are
// the same element symbol (NA in NA, CL in CL, ZN in ZN) is that element;
// any other name starts with its element's one letter (CA in ALA is carbon
// alpha, OW is oxygen, HW1 hydrogen), leading digits (1HB) left out.
const Element& element_of_name(std::string_view atom, std::string_view residue,
                               std::unordered_map<std::string, std::size_t>& unknown) {
    while (!atom.empty() && std::isdigit(static_cast<unsigned char>(atom.front()))) atom.remove_prefix(1);
    if (atom.empty()) return element_of_symbol("?", unknown);
    if (atom.size() <= 2 && atom.size() == residue.size() &&
        std::equal(atom.begin(), atom.end(), residue.begin(),
                   [](char a, char b) { return std::toupper(static_cast<unsigned char>(a)) == std::toupper(static_cast<unsigned char>(b)); }))
        if (const Element* ion = find_element(atom)) return *ion;
    return element_of_symbol(atom.substr(0, 1), unknown);
}

AtomFrame read_gro_frame(LineReader& lines, const std::string& source) {
    std::size_t count = 0;
    if (!read_start(lines, source, count)) throw InputError(source + ": expected a .gro frame, found the end of the file");
    AtomFrame frame;
    frame.positions.resize(count);
    frame.elements.resize(count);
    CategoryColumn elements("element"), residue_names("residue_name"), atom_names("atom_name");
    SphereProperty residue_numbers{"residue_number", {}, {}};
    SphereProperty velocity[3] = {{"vx", {}, {}}, {"vy", {}, {}}, {"vz", {}, {}}};
    std::unordered_map<std::string, std::size_t> unknown;
    // The width of a coordinate: the distance between the first two decimal
    // points of the first atom line (8 in files written with %8.3f).
    std::size_t width = 8;
    bool velocities = false;
    std::string_view line;
    for (std::size_t i = 0; i < count; ++i) {
        if (!lines.next(line))
            fail_at(source, lines.line_number() + 1,
                    "expected atom " + std::to_string(i + 1) + " of " + std::to_string(count) + ", found the end of the file");
        const std::uint64_t number = lines.line_number();
        if (i == 0) {
            const std::size_t first = line.find('.', 20), second = first == std::string_view::npos ? first : line.find('.', first + 1);
            if (second != std::string_view::npos && second - first >= 5 && second - first <= 20) width = second - first;
            velocities = line.size() >= 20 + 6 * width;
        }
        if (line.size() < 20 + 3 * width)
            fail_at(source, number,
                    "atom " + std::to_string(i + 1) + ": expected the fixed columns of a .gro atom line (residue number 1-5, residue name 6-10, atom name 11-15, atom number 16-20, x y z in " +
                        std::to_string(width) + " columns each from 21), got " + quoted_excerpt(line));
        for (int k = 0; k < 3; ++k) {
            const std::string_view text = trimmed(line.substr(20 + k * width, width));
            if (!parse_double(text, frame.positions[i][k]))
                fail_at(source, number, "atom " + std::to_string(i + 1) + ": expected a coordinate in columns " +
                                            std::to_string(21 + k * width) + "-" + std::to_string(20 + (k + 1) * width) +
                                            ", got " + quoted_excerpt(text));
            frame.positions[i][k] *= kAngstromPerNm;
        }
        if (velocities) {
            for (int k = 0; k < 3; ++k) {
                double v = 0;
                const std::string_view text = trimmed(line.substr(std::min(line.size(), 20 + (3 + k) * width), width));
                if (!parse_double(text, v))
                    fail_at(source, number, "atom " + std::to_string(i + 1) + ": expected a velocity (as the first atom has), got " + quoted_excerpt(text));
                velocity[k].values.push_back(property_value(v, source, number, velocity[k].name));
            }
        }
        long long residue = 0;
        const std::string_view residue_text = trimmed(line.substr(0, 5));
        if (!parse_long(residue_text, residue))
            fail_at(source, number, "atom " + std::to_string(i + 1) + ": expected a residue number in columns 1-5, got " + quoted_excerpt(residue_text));
        residue_numbers.values.push_back(static_cast<float>(residue));
        const std::string_view residue_name = trimmed(line.substr(5, 5)), atom_name = trimmed(line.substr(10, 5));
        residue_names.add(residue_name);
        atom_names.add(atom_name);
        frame.elements[i] = &element_of_name(atom_name, residue_name, unknown);
        elements.add(frame.elements[i]->number ? frame.elements[i]->symbol : atom_name);
    }
    if (!lines.next(line)) fail_at(source, lines.line_number() + 1, "expected the box line, found the end of the file");
    const std::vector<std::string_view> fields = split_fields(line);
    double box[9] = {};
    bool ok = fields.size() == 3 || fields.size() == 9;
    for (std::size_t k = 0; ok && k < fields.size(); ++k) ok = parse_double(fields[k], box[k]);
    if (!ok) fail_at(source, lines.line_number(), "expected the box: 3 or 9 numbers (nm), got " + quoted_excerpt(line));
    // v1(x) v2(y) v3(z) v1(y) v1(z) v2(x) v2(z) v3(x) v3(y)
    Cell cell;
    cell.a = {box[0] * kAngstromPerNm, box[3] * kAngstromPerNm, box[4] * kAngstromPerNm};
    cell.b = {box[5] * kAngstromPerNm, box[1] * kAngstromPerNm, box[6] * kAngstromPerNm};
    cell.c = {box[7] * kAngstromPerNm, box[8] * kAngstromPerNm, box[2] * kAngstromPerNm};
    frame.cell = cell;

    frame.properties.push_back(elements.take());
    frame.properties.push_back(residue_names.take());
    frame.properties.push_back(std::move(residue_numbers));
    frame.properties.push_back(atom_names.take());
    if (velocities)
        for (SphereProperty& v : velocity) frame.properties.push_back(std::move(v));
    if (std::string warning = unknown_elements_warning(source, unknown); !warning.empty())
        frame.warnings.push_back(std::move(warning));
    return frame;
}

constexpr TextFormat kGroFormat{"gro", skip_gro_frame, read_gro_frame};

}  // namespace

}  // namespace orb::molecular

namespace orb::detail {
namespace {

ContentMatch recognise_gro(std::string_view bytes) {
    // A title, a count alone, then fixed-column atoms with decimal points at
    // the coordinates' places.
    const std::string_view text = recognised_head(bytes);
    const std::vector<std::string_view> lines = head_lines(text, 3);
    if (lines.size() < 3) return ContentMatch::No;
    const std::vector<std::string_view> second = molecular::split_fields(lines[1]);
    const bool gro = second.size() == 1 && is_count_word(second[0]) && lines[2].size() >= 44 && lines[2][24] == '.' &&
                     lines[2][32] == '.' && lines[2][40] == '.';
    return gro ? ContentMatch::Yes : ContentMatch::No;
}

}  // namespace

const SceneImporter& gro_importer() {
    static const SceneImporter importer = molecular::text_trajectory_importer<molecular::kGroFormat>({
        .name = "gro",
        .description = "GROMACS .gro: an atom per sphere, each frame a frame (nm become angstrom)",
        .extensions = {".gro"},
        .extension_decides = true,
        .recognise = recognise_gro});
    return importer;
}

}  // namespace orb::detail

// LAMMPS dump frames (the "atom" and "custom" styles, text): ITEM: TIMESTEP,
// ITEM: NUMBER OF ATOMS, ITEM: BOX BOUNDS (orthogonal or triclinic), then
// ITEM: ATOMS with the names of its columns and one line per atom. The
// section layout is LAMMPS's "dump" command documentation's.
#include <algorithm>
#include <array>
#include <optional>
#include <unordered_map>

#include "orb/scene/error.h"
#include "importer_entries.h"
#include "text_start.h"
#include "text_trajectory.h"

namespace orb::molecular {
namespace {

constexpr std::string_view kItem = "ITEM:";

// The section an ITEM line opens, in words after "ITEM:".
std::string_view item_of(std::string_view line) {
    std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string_view::npos) return {};
    line.remove_prefix(start);
    if (!line.starts_with(kItem)) return {};
    line.remove_prefix(kItem.size());
    start = line.find_first_not_of(" \t");
    return start == std::string_view::npos ? std::string_view{} : line.substr(start);
}

[[noreturn]] void expected_item(const std::string& source, std::uint64_t line_number, std::string_view line) {
    fail_at(source, line_number,
            "expected a LAMMPS dump section (ITEM: TIMESTEP, ITEM: NUMBER OF ATOMS, ITEM: BOX BOUNDS, ITEM: ATOMS), got " +
                quoted_excerpt(line));
}

std::string next_value(LineReader& lines, const std::string& source, std::string_view what) {
    std::string_view line;
    if (!lines.next(line)) fail_at(source, lines.line_number() + 1, "expected " + std::string(what) + ", found the end of the file");
    return std::string(line);
}

std::size_t parse_dump_count(std::string_view text, const std::string& source, std::uint64_t line) {
    const std::vector<std::string_view> fields = split_fields(text);
    long long count = -1;
    if (fields.size() != 1 || !parse_long(fields[0], count) || count < 0 || count > 2'000'000'000LL)
        fail_at(source, line, "expected the number of atoms, got " + quoted_excerpt(text));
    return static_cast<std::size_t>(count);
}

// The header of a frame, up to and including its ITEM: ATOMS line.
struct Header {
    std::optional<std::size_t> atoms;
    std::optional<Cell> cell;
    std::string atoms_line;
    std::uint64_t atoms_line_number = 0;
    bool scaled_box_needed = false;
};

// Reads the sections before ITEM: ATOMS; false at the end of the input.
// `parse` also reads the box (the scan only counts its lines).
bool read_header(LineReader& lines, const std::string& source, bool parse, Header& header) {
    std::string_view line;
    if (!next_nonblank(lines, line)) return false;
    for (;;) {
        const std::string_view item = item_of(line);
        const std::uint64_t number = lines.line_number();
        if (item.starts_with("ATOMS")) {
            if (!header.atoms) fail_at(source, number, "ITEM: ATOMS before ITEM: NUMBER OF ATOMS");
            header.atoms_line = std::string(item);
            header.atoms_line_number = number;
            return true;
        }
        if (item == "TIMESTEP" || item == "TIME" || item.starts_with("UNITS")) {
            next_value(lines, source, "the value of ITEM: " + std::string(item));
        } else if (item == "NUMBER OF ATOMS") {
            header.atoms = parse_dump_count(next_value(lines, source, "the number of atoms"), source, lines.line_number());
        } else if (item.starts_with("BOX BOUNDS")) {
            const bool triclinic = split_fields(item).size() >= 5 && split_fields(item)[2] == "xy";
            double bounds[3][3] = {};
            for (int axis = 0; axis < 3; ++axis) {
                const std::string text = next_value(lines, source, "a line of the box bounds");
                if (!parse) continue;
                const std::vector<std::string_view> fields = split_fields(text);
                const std::size_t wanted = triclinic ? 3 : 2;
                bool ok = fields.size() >= wanted;
                for (std::size_t k = 0; ok && k < wanted; ++k) ok = parse_double(fields[k], bounds[axis][k]);
                if (!ok)
                    fail_at(source, lines.line_number(),
                            "expected " + std::string(triclinic ? "lo hi tilt" : "lo hi") + " of the box, got " + quoted_excerpt(text));
            }
            if (parse) {
                // Triclinic boxes are written with their bounding box: take the tilts back out (LAMMPS "Triclinic simulation boxes").
                double xlo = bounds[0][0], xhi = bounds[0][1], ylo = bounds[1][0], yhi = bounds[1][1];
                const double zlo = bounds[2][0], zhi = bounds[2][1];
                const double xy = bounds[0][2], xz = bounds[1][2], yz = bounds[2][2];
                if (triclinic) {
                    xlo -= std::min({0.0, xy, xz, xy + xz});
                    xhi -= std::max({0.0, xy, xz, xy + xz});
                    ylo -= std::min(0.0, yz);
                    yhi -= std::max(0.0, yz);
                }
                Cell cell;
                cell.origin = {xlo, ylo, zlo};
                cell.a = {xhi - xlo, 0, 0};
                cell.b = {xy, yhi - ylo, 0};
                cell.c = {xz, yz, zhi - zlo};
                header.cell = cell;
            }
        } else {
            expected_item(source, number, line);
        }
        if (!lines.next(line))
            fail_at(source, lines.line_number() + 1, "expected ITEM: ATOMS, found the end of the file");
    }
}

bool skip_dump_frame(LineReader& lines, const std::string& source) {
    Header header;
    if (!read_header(lines, source, false, header)) return false;
    const std::uint64_t got = lines.skip(*header.atoms);
    if (got < *header.atoms)
        fail_at(source, header.atoms_line_number,
                "the frame has " + std::to_string(*header.atoms) + " atoms, but the file ends after " + std::to_string(got) +
                    " atom lines (truncated?)");
    return true;
}

// Which columns hold the positions: x y z first, then the unwrapped xu yu zu,
// then the scaled xs ys zs and xsu ysu zsu (fractions of the box).
struct Positions {
    std::array<std::size_t, 3> columns{};
    bool scaled = false;
};

std::optional<Positions> find_positions(const std::vector<std::string_view>& names) {
    const auto index = [&names](std::string_view name) -> std::optional<std::size_t> {
        const auto found = std::find(names.begin(), names.end(), name);
        if (found == names.end()) return std::nullopt;
        return static_cast<std::size_t>(found - names.begin());
    };
    const struct {
        std::string_view x, y, z;
        bool scaled;
    } choices[] = {{"x", "y", "z", false}, {"xu", "yu", "zu", false}, {"xs", "ys", "zs", true}, {"xsu", "ysu", "zsu", true}};
    for (const auto& choice : choices) {
        const auto x = index(choice.x), y = index(choice.y), z = index(choice.z);
        if (x && y && z) return Positions{{*x, *y, *z}, choice.scaled};
    }
    return std::nullopt;
}

AtomFrame read_dump_frame(LineReader& lines, const std::string& source) {
    Header header;
    if (!read_header(lines, source, true, header))
        throw InputError(source + ": expected a LAMMPS dump frame, found the end of the file");
    std::vector<std::string_view> names = split_fields(header.atoms_line);
    names.erase(names.begin());  // "ATOMS"
    const std::optional<Positions> positions = find_positions(names);
    if (!positions)
        fail_at(source, header.atoms_line_number,
                "ITEM: ATOMS names no positions: expected the columns x y z, xu yu zu, xs ys zs or xsu ysu zsu, got " +
                    quoted_excerpt(header.atoms_line));
    if (positions->scaled && !header.cell)
        fail_at(source, header.atoms_line_number, "scaled positions (xs ys zs) but no ITEM: BOX BOUNDS before them");

    const std::size_t count = *header.atoms;
    AtomFrame frame;
    frame.cell = header.cell;
    frame.positions.resize(count);
    // The other columns: element (the atoms' elements), type (a category),
    // radius or diameter (the atoms' sizes), anything else a number.
    std::optional<std::size_t> element_column, type_column, radius_column, diameter_column, id_column;
    std::vector<std::pair<std::size_t, SphereProperty>> numeric;
    for (std::size_t c = 0; c < names.size(); ++c) {
        if (std::find(positions->columns.begin(), positions->columns.end(), c) != positions->columns.end()) continue;
        if (names[c] == "element") element_column = c;
        else if (names[c] == "type") type_column = c;
        else {
            if (names[c] == "radius") radius_column = c;
            if (names[c] == "diameter") diameter_column = c;
            if (names[c] == "id") id_column = c;
            numeric.push_back({c, SphereProperty{std::string(names[c]), {}, {}}});
            numeric.back().second.values.reserve(count);
        }
    }
    std::optional<CategoryColumn> elements, types;
    std::unordered_map<std::string, std::size_t> unknown;
    if (element_column) {
        elements.emplace("element");
        frame.elements.resize(count);
    }
    if (type_column) types.emplace("type");
    if (radius_column || diameter_column) frame.radii.resize(count);

    // An atom id names one atom of the frame: two lines with one id are a
    // broken dump (chemfiles refuses it too), not two atoms.
    std::unordered_map<long long, std::uint64_t> id_lines;
    if (id_column) id_lines.reserve(count);

    std::string_view line;
    std::vector<std::string_view> fields;
    for (std::size_t i = 0; i < count; ++i) {
        if (!lines.next(line))
            fail_at(source, lines.line_number() + 1,
                    "expected atom " + std::to_string(i + 1) + " of " + std::to_string(count) + ", found the end of the file");
        split_fields(line, fields);
        if (fields.size() != names.size())
            fail_at(source, lines.line_number(),
                    "expected " + std::to_string(names.size()) + " columns (as ITEM: ATOMS names them), got " +
                        std::to_string(fields.size()) + ": " + quoted_excerpt(line));
        Vec3 p;
        for (int k = 0; k < 3; ++k)
            if (!parse_double(fields[positions->columns[k]], p[k]))
                fail_at(source, lines.line_number(), "expected a number in column " + quoted_excerpt(names[positions->columns[k]]) +
                                                         ", got " + quoted_excerpt(fields[positions->columns[k]]));
        if (positions->scaled) {
            const Cell& cell = *header.cell;
            Vec3 q = cell.origin;
            for (int k = 0; k < 3; ++k) q[k] += p[0] * cell.a[k] + p[1] * cell.b[k] + p[2] * cell.c[k];
            p = q;
        }
        frame.positions[i] = p;
        // (An id that is not a whole number stays a number like any other column's.)
        if (long long id = 0; id_column && parse_long(fields[*id_column], id)) {
            const auto [first, fresh] = id_lines.emplace(id, lines.line_number());
            if (!fresh)
                fail_at(source, lines.line_number(),
                        "atom id " + std::to_string(id) + " appears twice in the frame (first on line " +
                            std::to_string(first->second) + "); each atom of a dump frame has its own id");
        }
        if (elements) {
            frame.elements[i] = &element_of_symbol(fields[*element_column], unknown);
            elements->add(frame.elements[i]->number ? frame.elements[i]->symbol : fields[*element_column]);
        }
        if (types) types->add(fields[*type_column]);
        for (auto& [column, property] : numeric) {
            double value = 0;
            if (!parse_double(fields[column], value))
                fail_at(source, lines.line_number(),
                        "expected a number in column " + quoted_excerpt(names[column]) + ", got " + quoted_excerpt(fields[column]));
            property.values.push_back(property_value(value, source, lines.line_number(), names[column]));
            if ((column == radius_column || column == diameter_column) && !(value > 0))
                fail_at(source, lines.line_number(), "expected a " + std::string(names[column]) + " > 0, got " + quoted_excerpt(fields[column]));
            if (column == radius_column) frame.radii[i] = value;
            else if (column == diameter_column && !radius_column) frame.radii[i] = value / 2;
        }
    }
    if (elements) frame.properties.push_back(elements->take());
    if (types) frame.properties.push_back(types->take());
    for (auto& entry : numeric) frame.properties.push_back(std::move(entry.second));
    if (std::string warning = unknown_elements_warning(source, unknown); !warning.empty())
        frame.warnings.push_back(std::move(warning));
    return frame;
}

constexpr TextFormat kLammpsDumpFormat{"lammps-dump", skip_dump_frame, read_dump_frame};

}  // namespace

}  // namespace orb::molecular

namespace orb::detail {
namespace {

ContentMatch recognise_lammps_dump(std::string_view bytes) {
    const std::string_view text = recognised_head(bytes);
    return first_line(text).starts_with("ITEM:") ? ContentMatch::Yes : ContentMatch::No;
}

}  // namespace

const SceneImporter& lammps_dump_importer() {
    static const SceneImporter importer = molecular::text_trajectory_importer<molecular::kLammpsDumpFormat>({
        .name = "lammps-dump",
        .aliases = {"lammpstrj"},
        .description = "LAMMPS text dump (atom or custom style): a particle per sphere, each timestep a frame",
        .extensions = {".lammpstrj", ".dump"},
        .extension_decides = true,
        .recognise = recognise_lammps_dump});
    return importer;
}

}  // namespace orb::detail

// XYZ and extended XYZ frames. An XYZ frame is an atom count, a comment line
// and one line per atom, "Element x y z" and perhaps more columns. Extended
// XYZ (the convention of ASE and QUIP/libatoms) writes key=value pairs on the
// comment line: Properties=species:S:1:pos:R:3:... names every column (name,
// type S/R/I/L, column count) and Lattice="ax ay az bx by bz cx cy cz" the cell.
#include <algorithm>
#include <cctype>
#include <optional>

#include "orb/scene/error.h"
#include "importer_entries.h"
#include "text_start.h"
#include "text_trajectory.h"

namespace orb::molecular {
namespace {

bool same_word(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

// The count line: one whole number (extra words are tolerated, as writers add them).
std::size_t atom_count(std::string_view line, const std::string& source, std::uint64_t number) {
    const std::vector<std::string_view> fields = split_fields(line);
    long long count = -1;
    if (fields.empty() || !parse_long(fields[0], count) || count < 0)
        fail_at(source, number, "expected the number of atoms of an XYZ frame, got " + quoted_excerpt(line));
    if (count > 2'000'000'000LL) fail_at(source, number, "implausible atom count " + std::to_string(count));
    return static_cast<std::size_t>(count);
}

// The comment line's key=value pairs; a value may be "quoted" (with spaces).
std::vector<std::pair<std::string, std::string>> key_values(std::string_view line) {
    std::vector<std::pair<std::string, std::string>> pairs;
    std::size_t i = 0;
    const auto space = [&] { return i < line.size() && (line[i] == ' ' || line[i] == '\t'); };
    while (i < line.size()) {
        while (space()) ++i;
        const std::size_t key_start = i;
        while (i < line.size() && line[i] != '=' && !space()) ++i;
        std::string key(line.substr(key_start, i - key_start));
        std::string value;
        if (i < line.size() && line[i] == '=') {
            ++i;
            if (i < line.size() && (line[i] == '"' || line[i] == '{')) {
                const char close = line[i] == '"' ? '"' : '}';
                const std::size_t end = line.find(close, i + 1);
                value = std::string(line.substr(i + 1, end == std::string_view::npos ? std::string_view::npos : end - i - 1));
                i = end == std::string_view::npos ? line.size() : end + 1;
            } else {
                const std::size_t value_start = i;
                while (i < line.size() && !space()) ++i;
                value = std::string(line.substr(value_start, i - value_start));
            }
        }
        if (!key.empty()) pairs.emplace_back(std::move(key), std::move(value));
    }
    return pairs;
}

// One column group of Properties=.
struct Column {
    std::string name;
    char type = 'R';  // S string, R real, I integer, L logical
    int count = 1;
    std::size_t first_field = 0;
};

std::vector<Column> parse_properties(const std::string& text, const std::string& source, std::uint64_t line) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= text.size(); ++i)
        if (i == text.size() || text[i] == ':') {
            parts.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    if (parts.size() % 3 != 0)
        fail_at(source, line, "Properties=" + quoted_excerpt(text) + ": expected name:type:count triples");
    std::vector<Column> columns;
    std::size_t field = 0;
    for (std::size_t p = 0; p < parts.size(); p += 3) {
        Column column;
        column.name = parts[p];
        const std::string& type = parts[p + 1];
        long long count = 0;
        if (column.name.empty() || type.size() != 1 || std::string_view("SRIL").find(type[0]) == std::string_view::npos ||
            !parse_long(parts[p + 2], count) || count < 1 || count > 1000)
            fail_at(source, line,
                    "Properties=" + quoted_excerpt(text) + ": expected name:type:count with type S, R, I or L and a count of 1 or more, got " +
                        quoted_excerpt(parts[p] + ":" + type + ":" + parts[p + 2]));
        column.type = type[0];
        column.count = static_cast<int>(count);
        column.first_field = field;
        field += static_cast<std::size_t>(count);
        columns.push_back(std::move(column));
    }
    return columns;
}

bool skip_xyz_frame(LineReader& lines, const std::string& source) {
    std::string_view line;
    if (!next_nonblank(lines, line)) return false;
    const std::uint64_t count_line = lines.line_number();
    const std::size_t count = atom_count(line, source, count_line);
    const std::uint64_t wanted = count + 1;
    const std::uint64_t got = lines.skip(wanted);
    if (got < wanted)
        fail_at(source, count_line,
                "the frame announces " + std::to_string(count) + " atoms, but the file ends after " +
                    std::to_string(got == 0 ? 0 : got - 1) + " atom lines (truncated?)");
    return true;
}

AtomFrame read_xyz_frame(LineReader& lines, const std::string& source) {
    std::string_view line;
    if (!next_nonblank(lines, line)) throw InputError(source + ": expected an XYZ frame, found the end of the file");
    const std::size_t count = atom_count(line, source, lines.line_number());
    if (!lines.next(line)) fail_at(source, lines.line_number() + 1, "expected the comment line of an XYZ frame");
    const std::uint64_t comment_line = lines.line_number();

    AtomFrame frame;
    // The default columns, extended XYZ's when Properties= is not given.
    std::vector<Column> columns{{"species", 'S', 1, 0}, {"pos", 'R', 3, 1}};
    bool extended = false;
    for (const auto& [key, value] : key_values(line)) {
        if (same_word(key, "Properties")) {
            columns = parse_properties(value, source, comment_line);
            extended = true;
        } else if (same_word(key, "Lattice")) {
            std::vector<std::string_view> numbers = split_fields(value);
            double v[9];
            bool ok = numbers.size() == 9;
            for (std::size_t i = 0; ok && i < 9; ++i) ok = parse_double(numbers[i], v[i]);
            if (!ok) fail_at(source, comment_line, "Lattice=" + quoted_excerpt(value) + ": expected 9 numbers (the cell vectors a, b, c)");
            Cell cell;
            cell.a = {v[0], v[1], v[2]};
            cell.b = {v[3], v[4], v[5]};
            cell.c = {v[6], v[7], v[8]};
            frame.cell = cell;
            extended = true;
        }
    }
    const auto find = [&columns](std::string_view name) -> const Column* {
        for (const Column& column : columns)
            if (same_word(column.name, name)) return &column;
        return nullptr;
    };
    const Column* pos = find("pos");  // pointers into `columns`: found again if it grows
    const Column* species = find("species");
    const Column* z = find("Z");
    if (!pos || pos->type != 'R' || pos->count != 3)
        fail_at(source, comment_line, "Properties= has no pos:R:3 column (the atoms' positions)");
    if (!species && !z) fail_at(source, comment_line, "Properties= has neither species:S:1 nor Z:I:1 (the atoms' elements)");
    const Column* element_column = species ? species : z;  // found again if `columns` grows
    std::size_t fields_needed = 0;
    for (const Column& column : columns) fields_needed = std::max(fields_needed, column.first_field + column.count);

    // Every other column becomes a property; several-wide ones one per component (forces_1, forces_2, ...).
    struct Output {
        const Column* column;
        int component;
        SphereProperty numeric;
        std::optional<CategoryColumn> category;
    };
    std::vector<Output> outputs;
    for (const Column& column : columns) {
        if (&column == pos || &column == element_column) continue;
        for (int k = 0; k < column.count; ++k) {
            Output output{&column, k, {}, std::nullopt};
            const std::string name = column.count == 1 ? column.name : column.name + "_" + std::to_string(k + 1);
            if (column.type == 'S')
                output.category.emplace(name);
            else
                output.numeric.name = name;
            outputs.push_back(std::move(output));
        }
    }
    // Plain XYZ: columns after x y z become column_5, column_6, ... (found on the first atom line).
    bool plain_extra_known = extended;

    frame.positions.resize(count);
    frame.elements.resize(count);
    CategoryColumn element_names("element");
    element_names.reserve(count);
    std::unordered_map<std::string, std::size_t> unknown;
    std::vector<std::string_view> fields;
    for (std::size_t i = 0; i < count; ++i) {
        if (!lines.next(line))
            fail_at(source, lines.line_number() + 1,
                    "expected atom " + std::to_string(i + 1) + " of " + std::to_string(count) + ", found the end of the file");
        split_fields(line, fields);
        if (!plain_extra_known) {
            // Plain XYZ: `outputs` is empty so far (species and pos are not
            // properties), so growing `columns` moves nothing it points to.
            plain_extra_known = true;
            for (std::size_t f = 4; f < fields.size(); ++f)
                columns.push_back({"column_" + std::to_string(f + 1), 'R', 1, f});
            pos = find("pos");
            element_column = find("species");
            for (std::size_t c = 2; c < columns.size(); ++c)
                outputs.push_back({&columns[c], 0, {columns[c].name, {}, {}}, std::nullopt});
            fields_needed = std::max<std::size_t>(4, fields.size());
        }
        if (fields.size() < fields_needed)
            fail_at(source, lines.line_number(),
                    "atom " + std::to_string(i + 1) + ": expected " + std::to_string(fields_needed) + " columns" +
                        (extended ? " (as Properties= says)" : " (element x y z and the first atom's other columns)") +
                        ", got " + std::to_string(fields.size()) + ": " + quoted_excerpt(line));
        for (int c = 0; c < 3; ++c)
            if (!parse_double(fields[pos->first_field + c], frame.positions[i][c]))
                fail_at(source, lines.line_number(),
                        "atom " + std::to_string(i + 1) + ": expected a coordinate, got " + quoted_excerpt(fields[pos->first_field + c]));
        const std::string_view symbol = fields[element_column->first_field];
        frame.elements[i] = &element_of_symbol(symbol, unknown);
        element_names.add(frame.elements[i]->number ? frame.elements[i]->symbol : symbol);
        for (Output& output : outputs) {
            const std::string_view text = fields[output.column->first_field + output.component];
            if (output.category) {
                output.category->add(text);
                continue;
            }
            double value = 0;
            if (output.column->type == 'L')
                value = text == "T" || text == "True" || text == "true" || text == "1" ? 1 : 0;
            else if (!parse_double(text, value))
                fail_at(source, lines.line_number(),
                        "atom " + std::to_string(i + 1) + ": column " + quoted_excerpt(output.numeric.name) +
                            ": expected a number, got " + quoted_excerpt(text));
            output.numeric.values.push_back(property_value(value, source, lines.line_number(), output.numeric.name));
        }
    }
    frame.properties.push_back(element_names.take());
    for (Output& output : outputs)
        frame.properties.push_back(output.category ? output.category->take() : std::move(output.numeric));
    if (std::string warning = unknown_elements_warning(source, unknown); !warning.empty())
        frame.warnings.push_back(std::move(warning));
    return frame;
}

constexpr TextFormat kXyzFormat{"xyz", skip_xyz_frame, read_xyz_frame};

}  // namespace

}  // namespace orb::molecular

namespace orb::detail {
namespace {

ContentMatch recognise_xyz(std::string_view bytes) {
    // A count alone on the first line (extra words are tolerated), then the
    // comment line, then (when there is one) an atom: a name and three numbers.
    const std::string_view text = recognised_head(bytes);
    const std::vector<std::string_view> lines = head_lines(text, 3);
    if (lines.size() < 2) return ContentMatch::No;
    const std::vector<std::string_view> count = molecular::split_fields(lines[0]);
    if (count.empty() || count.size() > 2 || !is_count_word(count[0])) return ContentMatch::No;
    if (lines.size() < 3) return ContentMatch::Yes;
    const std::vector<std::string_view> atom = molecular::split_fields(lines[2]);
    double number = 0;
    const bool is_atom = atom.size() >= 4 && std::isalnum(static_cast<unsigned char>(atom[0].front())) &&
                         molecular::parse_double(atom[1], number) && molecular::parse_double(atom[2], number) &&
                         molecular::parse_double(atom[3], number);
    return is_atom ? ContentMatch::Yes : ContentMatch::No;
}

}  // namespace

const SceneImporter& xyz_importer() {
    static const SceneImporter importer = molecular::text_trajectory_importer<molecular::kXyzFormat>({
        .name = "xyz",
        .aliases = {"extxyz"},
        .description = "XYZ or extended XYZ: an atom per sphere, each frame of a trajectory a frame",
        .extensions = {".xyz", ".extxyz"},
        .extension_decides = true,
        .recognise = recognise_xyz});
    return importer;
}

}  // namespace orb::detail

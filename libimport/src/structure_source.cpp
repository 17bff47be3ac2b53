#include "structure_source.h"

#include <gemmi/mmcif.hpp>
#include <gemmi/pdb.hpp>
#include <gemmi/cif.hpp>

#include <atomic>
#include <cmath>
#include <map>

#include "atom_frame.h"
#include "atoms_scene.h"
#include "line_reader.h"
#include "orb/scene/error.h"

namespace orb::molecular {
namespace {

// The conformer a residue keeps by default: the alternate location whose
// atoms have the largest occupancy in sum, the first one listed on a tie.
char kept_altloc(const gemmi::Residue& residue) {
    std::vector<std::pair<char, double>> sums;
    for (const gemmi::Atom& atom : residue.atoms) {
        if (!atom.altloc) continue;
        auto found = std::find_if(sums.begin(), sums.end(), [&](const auto& s) { return s.first == atom.altloc; });
        if (found == sums.end()) sums.push_back({atom.altloc, atom.occ});
        else found->second += atom.occ;
    }
    char best = 0;
    double most = -1;
    for (const auto& [altloc, sum] : sums)
        if (sum > most) best = altloc, most = sum;
    return best;
}

// The unit cell of a crystal structure (CRYST1, _cell); none for the 1 1 1 placeholder of NMR entries.
std::optional<Cell> cell_of(const gemmi::Structure& structure) {
    const gemmi::UnitCell& unit = structure.cell;
    if (!unit.is_crystal() || !(unit.a > 1.0 && unit.b > 1.0 && unit.c > 1.0)) return std::nullopt;
    Cell cell;
    const gemmi::Mat33& m = unit.orth.mat;  // columns: the cell vectors in Cartesian angstrom
    cell.a = {m[0][0], m[1][0], m[2][0]};
    cell.b = {m[0][1], m[1][1], m[2][1]};
    cell.c = {m[0][2], m[1][2], m[2][2]};
    return cell;
}

AtomFrame model_frame(const gemmi::Structure& structure, const gemmi::Model& model,
                      const MolecularImportOptions& options) {
    AtomFrame frame;
    CategoryColumn elements("element"), chains("chain"), residue_names("residue_name"), atom_names("atom_name");
    SphereProperty residue_numbers{"residue_number", {}, {}}, b_factors{"b_factor", {}, {}},
        occupancies{"occupancy", {}, {}};
    std::optional<CategoryColumn> altlocs;
    if (options.all_altlocs) altlocs.emplace("altloc");
    std::unordered_map<std::string, std::size_t> unknown;
    for (const gemmi::Chain& chain : model.chains)
        for (const gemmi::Residue& residue : chain.residues) {
            const char keep = options.all_altlocs ? 0 : kept_altloc(residue);
            for (const gemmi::Atom& atom : residue.atoms) {
                if (!options.all_altlocs && atom.altloc && atom.altloc != keep) continue;
                if (options.drop_hydrogens && atom.is_hydrogen()) continue;
                frame.positions.push_back({atom.pos.x, atom.pos.y, atom.pos.z});
                const std::string symbol = atom.element.name();
                const Element& element =
                    atom.element == gemmi::El::X ? element_of_symbol(atom.name, unknown) : element_of_symbol(symbol, unknown);
                frame.elements.push_back(&element);
                elements.add(element.number ? element.symbol : std::string_view(symbol));
                chains.add(chain.name);
                residue_names.add(residue.name);
                residue_numbers.values.push_back(static_cast<float>(*residue.seqid.num));
                atom_names.add(atom.name);
                b_factors.values.push_back(atom.b_iso);
                occupancies.values.push_back(atom.occ);
                if (altlocs) altlocs->add(atom.altloc ? std::string(1, atom.altloc) : std::string("."));
            }
        }
    frame.properties.push_back(elements.take());
    frame.properties.push_back(chains.take());
    frame.properties.push_back(residue_names.take());
    frame.properties.push_back(std::move(residue_numbers));
    frame.properties.push_back(atom_names.take());
    frame.properties.push_back(std::move(b_factors));
    frame.properties.push_back(std::move(occupancies));
    if (altlocs) frame.properties.push_back(altlocs->take());
    frame.cell = cell_of(structure);
    return frame;
}

// gemmi reads a coordinate it cannot parse as 0; each ATOM/HETATM record's
// x, y and z (columns 31-38, 39-46, 47-54) must be numbers, or the file is refused.
void check_pdb_coordinates(std::string_view bytes, const std::string& source) {
    LineReader lines(bytes);
    std::string_view line;
    while (lines.next(line)) {
        if (!line.starts_with("ATOM  ") && !line.starts_with("HETATM")) continue;
        for (int k = 0; k < 3; ++k) {
            const std::size_t first = 30 + 8 * static_cast<std::size_t>(k);
            std::string_view text = line.substr(std::min(line.size(), first), 8);
            const std::size_t start = text.find_first_not_of(' ');
            text = start == std::string_view::npos ? std::string_view{} : text.substr(start, text.find_last_not_of(' ') - start + 1);
            double value = 0;
            if (!parse_double(text, value))
                fail_at(source, lines.line_number(),
                        std::string("expected the atom's ") + "xyz"[k] + " in columns " + std::to_string(first + 1) + "-" +
                            std::to_string(first + 8) + ", got " + quoted_excerpt(text));
        }
    }
}

class StructureSource final : public FrameSource {
public:
    StructureSource(gemmi::Structure structure, std::string source, std::string_view format,
                    const MolecularImportOptions& options)
        : structure_(std::move(structure)), source_(std::move(source)), format_(format), options_(options) {
        if (structure_.models.empty()) throw InputError(source_ + ": no atoms (no model in the file)");
        // Frame 1 fixes the camera and lights now, so that any frame can be read first.
        AtomFrame first = model_frame(structure_, structure_.models[0], options_);
        if (first.positions.empty())
            throw InputError(source_ + ": model 1 has no atoms" +
                             (options_.drop_hydrogens ? std::string(" (with hydrogens dropped)") : std::string()));
        warnings_ = std::move(first.warnings);
        atoms_scene(std::move(first), options_, view_, source_);
        ++built_;
    }

    std::size_t frame_count() const override { return structure_.models.size(); }
    Scene frame(std::size_t index) const override {
        if (index >= structure_.models.size())
            throw InputError(source_ + ": has " + std::to_string(structure_.models.size()) + " models; no frame " +
                             std::to_string(index + 1));
        FrameView view = view_;
        ++built_;
        return atoms_scene(model_frame(structure_, structure_.models[index], options_), options_, view, source_);
    }
    const std::vector<std::string>& warnings() const override { return warnings_; }
    std::string_view format() const override { return format_; }
    std::size_t frames_built() const override { return built_.load(); }

private:
    gemmi::Structure structure_;
    std::string source_;
    std::string_view format_;
    MolecularImportOptions options_;
    FrameView view_;
    std::vector<std::string> warnings_;
    mutable std::atomic<std::size_t> built_{0};
};

}  // namespace

std::unique_ptr<FrameSource> open_structure(std::string_view bytes, const std::string& source, std::string_view format,
                                            const MolecularImportOptions& options) {
    gemmi::Structure structure;
    try {
        if (format == "pdb") {
            check_pdb_coordinates(bytes, source);
            structure = gemmi::read_pdb_from_memory(bytes.data(), bytes.size(), source);
        } else {
            const gemmi::cif::Document document = gemmi::cif::read_memory(bytes.data(), bytes.size(), source.c_str());
            structure = gemmi::make_structure(document);
        }
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        // gemmi's messages name the line for PDB ("line 12: ...") and the place for CIF.
        std::string message = e.what();
        if (!message.starts_with(source)) message = source + ": " + message;
        throw InputError(message);
    }
    // Models without atoms (an empty MODEL/ENDMDL pair) are no frames.
    std::erase_if(structure.models, [](const gemmi::Model& model) {
        for (const gemmi::Chain& chain : model.chains)
            for (const gemmi::Residue& residue : chain.residues)
                if (!residue.atoms.empty()) return false;
        return true;
    });
    return std::make_unique<StructureSource>(std::move(structure), source, format, options);
}

}  // namespace orb::molecular

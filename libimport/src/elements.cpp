// The element table (orb/import/elements.h). Data, transcribed from published tables:
//   colours: Jmol's element colours (jmol.sourceforge.net/jscolors), as 8-bit sRGB;
//   van der Waals radii: A. Bondi, "van der Waals Volumes and Radii", J. Phys. Chem. 68, 441
//     (1964); where Bondi gives none, M. Mantina, A. C. Chamberlin, R. Valero, C. J. Cramer,
//     D. G. Truhlar, "Consistent van der Waals Radii for the Whole Main Group", J. Phys. Chem. A
//     113, 5806 (2009); where neither does, S. Alvarez, "A cartography of the van der Waals
//     territories", Dalton Trans. 42, 8617 (2013); where none does, kNoVdwRadius;
//   covalent radii: B. Cordero et al., "Covalent radii revisited", Dalton Trans. 2832 (2008),
//     Z = 1..96 (carbon: its sp3 value, 0.76); beyond, kNoCovalentRadius.
// Bondi's radii come first because molecular viewers size atoms by them (C 1.70, N 1.55,
// O 1.52): a protein looks as users know it.
#include "orb/import/elements.h"

#include <algorithm>
#include <cctype>

#include "srgb.h"

namespace orb {
namespace {

// symbol, Z, Jmol sRGB, vdW radius, its source, covalent radius, whether Cordero gives it
constexpr Element kElements[] = {
    {"H", 1, {0xFF, 0xFF, 0xFF}, 1.20, VdwSource::Bondi, 0.31, true},
    {"He", 2, {0xD9, 0xFF, 0xFF}, 1.40, VdwSource::Bondi, 0.28, true},
    {"Li", 3, {0xCC, 0x80, 0xFF}, 1.82, VdwSource::Bondi, 1.28, true},
    {"Be", 4, {0xC2, 0xFF, 0x00}, 1.53, VdwSource::Mantina, 0.96, true},
    {"B", 5, {0xFF, 0xB5, 0xB5}, 1.92, VdwSource::Mantina, 0.84, true},
    {"C", 6, {0x90, 0x90, 0x90}, 1.70, VdwSource::Bondi, 0.76, true},
    {"N", 7, {0x30, 0x50, 0xF8}, 1.55, VdwSource::Bondi, 0.71, true},
    {"O", 8, {0xFF, 0x0D, 0x0D}, 1.52, VdwSource::Bondi, 0.66, true},
    {"F", 9, {0x90, 0xE0, 0x50}, 1.47, VdwSource::Bondi, 0.57, true},
    {"Ne", 10, {0xB3, 0xE3, 0xF5}, 1.54, VdwSource::Bondi, 0.58, true},
    {"Na", 11, {0xAB, 0x5C, 0xF2}, 2.27, VdwSource::Bondi, 1.66, true},
    {"Mg", 12, {0x8A, 0xFF, 0x00}, 1.73, VdwSource::Bondi, 1.41, true},
    {"Al", 13, {0xBF, 0xA6, 0xA6}, 1.84, VdwSource::Mantina, 1.21, true},
    {"Si", 14, {0xF0, 0xC8, 0xA0}, 2.10, VdwSource::Bondi, 1.11, true},
    {"P", 15, {0xFF, 0x80, 0x00}, 1.80, VdwSource::Bondi, 1.07, true},
    {"S", 16, {0xFF, 0xFF, 0x30}, 1.80, VdwSource::Bondi, 1.05, true},
    {"Cl", 17, {0x1F, 0xF0, 0x1F}, 1.75, VdwSource::Bondi, 1.02, true},
    {"Ar", 18, {0x80, 0xD1, 0xE3}, 1.88, VdwSource::Bondi, 1.06, true},
    {"K", 19, {0x8F, 0x40, 0xD4}, 2.75, VdwSource::Bondi, 2.03, true},
    {"Ca", 20, {0x3D, 0xFF, 0x00}, 2.31, VdwSource::Mantina, 1.76, true},
    {"Sc", 21, {0xE6, 0xE6, 0xE6}, 2.58, VdwSource::Alvarez, 1.70, true},
    {"Ti", 22, {0xBF, 0xC2, 0xC7}, 2.46, VdwSource::Alvarez, 1.60, true},
    {"V", 23, {0xA6, 0xA6, 0xAB}, 2.42, VdwSource::Alvarez, 1.53, true},
    {"Cr", 24, {0x8A, 0x99, 0xC7}, 2.45, VdwSource::Alvarez, 1.39, true},
    {"Mn", 25, {0x9C, 0x7A, 0xC7}, 2.45, VdwSource::Alvarez, 1.39, true},
    {"Fe", 26, {0xE0, 0x66, 0x33}, 2.44, VdwSource::Alvarez, 1.32, true},
    {"Co", 27, {0xF0, 0x90, 0xA0}, 2.40, VdwSource::Alvarez, 1.26, true},
    {"Ni", 28, {0x50, 0xD0, 0x50}, 1.63, VdwSource::Bondi, 1.24, true},
    {"Cu", 29, {0xC8, 0x80, 0x33}, 1.40, VdwSource::Bondi, 1.32, true},
    {"Zn", 30, {0x7D, 0x80, 0xB0}, 1.39, VdwSource::Bondi, 1.22, true},
    {"Ga", 31, {0xC2, 0x8F, 0x8F}, 1.87, VdwSource::Bondi, 1.22, true},
    {"Ge", 32, {0x66, 0x8F, 0x8F}, 2.11, VdwSource::Mantina, 1.20, true},
    {"As", 33, {0xBD, 0x80, 0xE3}, 1.85, VdwSource::Bondi, 1.19, true},
    {"Se", 34, {0xFF, 0xA1, 0x00}, 1.90, VdwSource::Bondi, 1.20, true},
    {"Br", 35, {0xA6, 0x29, 0x29}, 1.85, VdwSource::Bondi, 1.20, true},
    {"Kr", 36, {0x5C, 0xB8, 0xD1}, 2.02, VdwSource::Bondi, 1.16, true},
    {"Rb", 37, {0x70, 0x2E, 0xB0}, 3.03, VdwSource::Mantina, 2.20, true},
    {"Sr", 38, {0x00, 0xFF, 0x00}, 2.49, VdwSource::Mantina, 1.95, true},
    {"Y", 39, {0x94, 0xFF, 0xFF}, 2.75, VdwSource::Alvarez, 1.90, true},
    {"Zr", 40, {0x94, 0xE0, 0xE0}, 2.52, VdwSource::Alvarez, 1.75, true},
    {"Nb", 41, {0x73, 0xC2, 0xC9}, 2.56, VdwSource::Alvarez, 1.64, true},
    {"Mo", 42, {0x54, 0xB5, 0xB5}, 2.45, VdwSource::Alvarez, 1.54, true},
    {"Tc", 43, {0x3B, 0x9E, 0x9E}, 2.44, VdwSource::Alvarez, 1.47, true},
    {"Ru", 44, {0x24, 0x8F, 0x8F}, 2.46, VdwSource::Alvarez, 1.46, true},
    {"Rh", 45, {0x0A, 0x7D, 0x8C}, 2.44, VdwSource::Alvarez, 1.42, true},
    {"Pd", 46, {0x00, 0x69, 0x85}, 1.63, VdwSource::Bondi, 1.39, true},
    {"Ag", 47, {0xC0, 0xC0, 0xC0}, 1.72, VdwSource::Bondi, 1.45, true},
    {"Cd", 48, {0xFF, 0xD9, 0x8F}, 1.58, VdwSource::Bondi, 1.44, true},
    {"In", 49, {0xA6, 0x75, 0x73}, 1.93, VdwSource::Bondi, 1.42, true},
    {"Sn", 50, {0x66, 0x80, 0x80}, 2.17, VdwSource::Bondi, 1.39, true},
    {"Sb", 51, {0x9E, 0x63, 0xB5}, 2.06, VdwSource::Mantina, 1.39, true},
    {"Te", 52, {0xD4, 0x7A, 0x00}, 2.06, VdwSource::Bondi, 1.38, true},
    {"I", 53, {0x94, 0x00, 0x94}, 1.98, VdwSource::Bondi, 1.39, true},
    {"Xe", 54, {0x42, 0x9E, 0xB0}, 2.16, VdwSource::Bondi, 1.40, true},
    {"Cs", 55, {0x57, 0x17, 0x8F}, 3.43, VdwSource::Mantina, 2.44, true},
    {"Ba", 56, {0x00, 0xC9, 0x00}, 2.49, VdwSource::Mantina, 2.15, true},
    {"La", 57, {0x70, 0xD4, 0xFF}, 2.98, VdwSource::Alvarez, 2.07, true},
    {"Ce", 58, {0xFF, 0xFF, 0xC7}, 2.88, VdwSource::Alvarez, 2.04, true},
    {"Pr", 59, {0xD9, 0xFF, 0xC7}, 2.92, VdwSource::Alvarez, 2.03, true},
    {"Nd", 60, {0xC7, 0xFF, 0xC7}, 2.95, VdwSource::Alvarez, 2.01, true},
    {"Pm", 61, {0xA3, 0xFF, 0xC7}, 2.00, VdwSource::None, 1.99, true},
    {"Sm", 62, {0x8F, 0xFF, 0xC7}, 2.90, VdwSource::Alvarez, 1.98, true},
    {"Eu", 63, {0x61, 0xFF, 0xC7}, 2.87, VdwSource::Alvarez, 1.98, true},
    {"Gd", 64, {0x45, 0xFF, 0xC7}, 2.83, VdwSource::Alvarez, 1.96, true},
    {"Tb", 65, {0x30, 0xFF, 0xC7}, 2.79, VdwSource::Alvarez, 1.94, true},
    {"Dy", 66, {0x1F, 0xFF, 0xC7}, 2.87, VdwSource::Alvarez, 1.92, true},
    {"Ho", 67, {0x00, 0xFF, 0x9C}, 2.81, VdwSource::Alvarez, 1.92, true},
    {"Er", 68, {0x00, 0xE6, 0x75}, 2.83, VdwSource::Alvarez, 1.89, true},
    {"Tm", 69, {0x00, 0xD4, 0x52}, 2.79, VdwSource::Alvarez, 1.90, true},
    {"Yb", 70, {0x00, 0xBF, 0x38}, 2.80, VdwSource::Alvarez, 1.87, true},
    {"Lu", 71, {0x00, 0xAB, 0x24}, 2.74, VdwSource::Alvarez, 1.87, true},
    {"Hf", 72, {0x4D, 0xC2, 0xFF}, 2.63, VdwSource::Alvarez, 1.75, true},
    {"Ta", 73, {0x4D, 0xA6, 0xFF}, 2.53, VdwSource::Alvarez, 1.70, true},
    {"W", 74, {0x21, 0x94, 0xD6}, 2.57, VdwSource::Alvarez, 1.62, true},
    {"Re", 75, {0x26, 0x7D, 0xAB}, 2.49, VdwSource::Alvarez, 1.51, true},
    {"Os", 76, {0x26, 0x66, 0x96}, 2.48, VdwSource::Alvarez, 1.44, true},
    {"Ir", 77, {0x17, 0x54, 0x87}, 2.41, VdwSource::Alvarez, 1.41, true},
    {"Pt", 78, {0xD0, 0xD0, 0xE0}, 1.75, VdwSource::Bondi, 1.36, true},
    {"Au", 79, {0xFF, 0xD1, 0x23}, 1.66, VdwSource::Bondi, 1.36, true},
    {"Hg", 80, {0xB8, 0xB8, 0xD0}, 1.55, VdwSource::Bondi, 1.32, true},
    {"Tl", 81, {0xA6, 0x54, 0x4D}, 1.96, VdwSource::Bondi, 1.45, true},
    {"Pb", 82, {0x57, 0x59, 0x61}, 2.02, VdwSource::Bondi, 1.46, true},
    {"Bi", 83, {0x9E, 0x4F, 0xB5}, 2.07, VdwSource::Mantina, 1.48, true},
    {"Po", 84, {0xAB, 0x5C, 0x00}, 1.97, VdwSource::Mantina, 1.40, true},
    {"At", 85, {0x75, 0x4F, 0x45}, 2.02, VdwSource::Mantina, 1.50, true},
    {"Rn", 86, {0x42, 0x82, 0x96}, 2.20, VdwSource::Mantina, 1.50, true},
    {"Fr", 87, {0x42, 0x00, 0x66}, 3.48, VdwSource::Mantina, 2.60, true},
    {"Ra", 88, {0x00, 0x7D, 0x00}, 2.83, VdwSource::Mantina, 2.21, true},
    {"Ac", 89, {0x70, 0xAB, 0xFA}, 2.80, VdwSource::Alvarez, 2.15, true},
    {"Th", 90, {0x00, 0xBA, 0xFF}, 2.93, VdwSource::Alvarez, 2.06, true},
    {"Pa", 91, {0x00, 0xA1, 0xFF}, 2.88, VdwSource::Alvarez, 2.00, true},
    {"U", 92, {0x00, 0x8F, 0xFF}, 1.86, VdwSource::Bondi, 1.96, true},
    {"Np", 93, {0x00, 0x80, 0xFF}, 2.82, VdwSource::Alvarez, 1.90, true},
    {"Pu", 94, {0x00, 0x6B, 0xFF}, 2.81, VdwSource::Alvarez, 1.87, true},
    {"Am", 95, {0x54, 0x5C, 0xF2}, 2.83, VdwSource::Alvarez, 1.80, true},
    {"Cm", 96, {0x78, 0x5C, 0xE3}, 3.05, VdwSource::Alvarez, 1.69, true},
    {"Bk", 97, {0x8A, 0x4F, 0xE3}, 3.40, VdwSource::Alvarez, 1.50, false},
    {"Cf", 98, {0xA1, 0x36, 0xD4}, 3.05, VdwSource::Alvarez, 1.50, false},
    {"Es", 99, {0xB3, 0x1F, 0xD4}, 2.70, VdwSource::Alvarez, 1.50, false},
    {"Fm", 100, {0xB3, 0x1F, 0xBA}, 2.00, VdwSource::None, 1.50, false},
    {"Md", 101, {0xB3, 0x0D, 0xA6}, 2.00, VdwSource::None, 1.50, false},
    {"No", 102, {0xBD, 0x0D, 0x87}, 2.00, VdwSource::None, 1.50, false},
    {"Lr", 103, {0xC7, 0x00, 0x66}, 2.00, VdwSource::None, 1.50, false},
    {"Rf", 104, {0xCC, 0x00, 0x59}, 2.00, VdwSource::None, 1.50, false},
    {"Db", 105, {0xD1, 0x00, 0x4F}, 2.00, VdwSource::None, 1.50, false},
    {"Sg", 106, {0xD9, 0x00, 0x45}, 2.00, VdwSource::None, 1.50, false},
    {"Bh", 107, {0xE0, 0x00, 0x38}, 2.00, VdwSource::None, 1.50, false},
    {"Hs", 108, {0xE6, 0x00, 0x2E}, 2.00, VdwSource::None, 1.50, false},
    {"Mt", 109, {0xEB, 0x00, 0x26}, 2.00, VdwSource::None, 1.50, false},
};
static_assert(std::size(kElements) == 109);

constexpr Element kUnknown{"X", 0, {0x80, 0x80, 0x80}, kNoVdwRadius, VdwSource::None, kNoCovalentRadius, false};

bool same_symbol(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

}  // namespace

std::span<const Element> elements() { return kElements; }

const Element* find_element(std::string_view symbol) {
    if (same_symbol(symbol, "D") || same_symbol(symbol, "T")) return &kElements[0];
    for (const Element& element : kElements)
        if (same_symbol(element.symbol, symbol)) return &element;
    return nullptr;
}

const Element* element_by_number(long number) {
    return number >= 1 && number <= static_cast<long>(std::size(kElements)) ? &kElements[number - 1] : nullptr;
}

const Element& unknown_element() { return kUnknown; }

Vec3 element_color(const Element& element) {
    Vec3 color;
    for (int c = 0; c < 3; ++c) color[c] = detail::srgb_to_linear(element.jmol_srgb[c] / 255.0);
    return color;
}

}  // namespace orb

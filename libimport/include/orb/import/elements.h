// The chemical elements, as molecular and particle readers colour and size
// atoms: symbol, atomic number, the Jmol colour, a van der Waals radius and a
// covalent radius. The sources of every number are in elements.cpp and
// docs/orb-import.md ("The element table").
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "orb/scene/vec3.h"

namespace orb {

// Which published table a van der Waals radius comes from.
enum class VdwSource {
    Bondi,    // A. Bondi, J. Phys. Chem. 68, 441 (1964)
    Mantina,  // M. Mantina et al., J. Phys. Chem. A 113, 5806 (2009): Bondi's method for the rest of the main groups
    Alvarez,  // S. Alvarez, Dalton Trans. 42, 8617 (2013): the other elements
    None,     // no published value: kNoVdwRadius
};

inline constexpr double kNoVdwRadius = 2.0;       // angstrom, for elements no table gives
inline constexpr double kNoCovalentRadius = 1.5;  // angstrom, beyond Cordero's Z = 96

struct Element {
    std::string_view symbol;                // "C", "Fe"
    int number = 0;                         // atomic number; 0 for the unknown element
    std::array<std::uint8_t, 3> jmol_srgb;  // Jmol's colour, 8-bit sRGB as Jmol lists it
    double vdw_radius = kNoVdwRadius;       // angstrom
    VdwSource vdw_source = VdwSource::None;
    double covalent_radius = kNoCovalentRadius;  // angstrom, B. Cordero et al., Dalton Trans. 2832 (2008)
    bool covalent_published = false;             // false: kNoCovalentRadius
};

// Hydrogen (1) to meitnerium (109), in order of atomic number.
std::span<const Element> elements();

// The element a symbol names, in any case ("FE", "fe", "Fe"); "D" and "T"
// (deuterium, tritium) are hydrogen. Null for anything else.
const Element* find_element(std::string_view symbol);

// The element with this atomic number (1..109); null otherwise.
const Element* element_by_number(long number);

// "X": what an atom whose element is not known is drawn as: grey (Jmol's
// colour for unknown atoms is not in its table; #808080 here), radius kNoVdwRadius / kNoCovalentRadius.
const Element& unknown_element();

// The element's Jmol colour as linear Rec.709 reflectance (the scene's colours).
Vec3 element_color(const Element& element);

}  // namespace orb

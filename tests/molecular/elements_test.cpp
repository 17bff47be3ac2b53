// The element table: complete, in order, and the published values the docs quote.
#include <gtest/gtest.h>

#include <cmath>

#include "orb/import/elements.h"

namespace orb {
namespace {

TEST(Elements, HydrogenToMeitneriumInOrder) {
    const auto table = elements();
    ASSERT_EQ(table.size(), 109u);
    for (std::size_t i = 0; i < table.size(); ++i) {
        EXPECT_EQ(table[i].number, static_cast<int>(i + 1));
        EXPECT_GT(table[i].vdw_radius, 0);
        EXPECT_GT(table[i].covalent_radius, 0);
        EXPECT_EQ(find_element(table[i].symbol), &table[i]) << table[i].symbol;
        EXPECT_EQ(element_by_number(table[i].number), &table[i]);
    }
    EXPECT_EQ(element_by_number(0), nullptr);
    EXPECT_EQ(element_by_number(110), nullptr);
}

TEST(Elements, SymbolsInAnyCaseAndHeavyHydrogen) {
    EXPECT_EQ(find_element("FE")->number, 26);
    EXPECT_EQ(find_element("fe")->number, 26);
    EXPECT_EQ(find_element("D")->number, 1);
    EXPECT_EQ(find_element("T")->number, 1);
    EXPECT_EQ(find_element("Xx"), nullptr);
    EXPECT_EQ(find_element(""), nullptr);
    EXPECT_EQ(unknown_element().number, 0);
}

// Values as the cited tables give them (elements.cpp names the sources).
TEST(Elements, PublishedRadiiAndColours) {
    const Element& c = *find_element("C");
    EXPECT_EQ(c.vdw_radius, 1.70);  // Bondi 1964
    EXPECT_EQ(c.vdw_source, VdwSource::Bondi);
    EXPECT_EQ(c.covalent_radius, 0.76);  // Cordero 2008, sp3
    EXPECT_EQ(find_element("N")->vdw_radius, 1.55);
    EXPECT_EQ(find_element("O")->vdw_radius, 1.52);
    EXPECT_EQ(find_element("H")->vdw_radius, 1.20);
    EXPECT_EQ(find_element("Al")->vdw_source, VdwSource::Mantina);
    EXPECT_EQ(find_element("Al")->vdw_radius, 1.84);
    EXPECT_EQ(find_element("Fe")->vdw_source, VdwSource::Alvarez);
    EXPECT_EQ(find_element("Fe")->vdw_radius, 2.44);
    EXPECT_EQ(find_element("Fe")->covalent_radius, 1.32);
    EXPECT_EQ(find_element("Mt")->vdw_source, VdwSource::None);
    EXPECT_EQ(find_element("Mt")->vdw_radius, kNoVdwRadius);
    // Jmol: C #909090, O #FF0D0D, N #3050F8.
    EXPECT_EQ(c.jmol_srgb, (std::array<std::uint8_t, 3>{0x90, 0x90, 0x90}));
    EXPECT_EQ(find_element("O")->jmol_srgb, (std::array<std::uint8_t, 3>{0xFF, 0x0D, 0x0D}));
    EXPECT_EQ(find_element("N")->jmol_srgb, (std::array<std::uint8_t, 3>{0x30, 0x50, 0xF8}));
}

TEST(Elements, ColoursAreLinear) {
    // sRGB 0x90 = 144/255 = 0.5647 decodes to ((0.5647 + 0.055) / 1.055)^2.4.
    const double expected = std::pow((144.0 / 255 + 0.055) / 1.055, 2.4);
    const Vec3 c = element_color(*find_element("C"));
    for (double v : c) EXPECT_NEAR(v, expected, 1e-12);
    EXPECT_EQ(element_color(*find_element("H")), (Vec3{1, 1, 1}));
}

}  // namespace
}  // namespace orb

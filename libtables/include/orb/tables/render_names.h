// The names of the integrator modes and the samplers (device_types.h's
// enums), one table each: what --mode and --sampler take, what a film's
// header says (orb:mode, orb:sampler), and what a render read back is set
// to. Host C++ only; the kernels' program does not include it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orb/tables/device_types.h"

namespace orb::device {

template <typename Enum>
struct Named {
    Enum value;
    std::string_view name;
};

// The first row of each table is the default.
inline constexpr std::array<Named<IntegratorMode>, 2> kIntegratorModeNames{{
    {IntegratorMode::Global, "global"},  // path tracing
    {IntegratorMode::Direct, "direct"},  // the paper's local illumination
}};
inline constexpr std::array<Named<SamplerKind>, 2> kSamplerNames{{
    {SamplerKind::Sobol, "sobol"},
    {SamplerKind::Independent, "independent"},
}};

// The name of `value` in `table`.
template <typename Enum, std::size_t N>
constexpr std::string_view name_in(const std::array<Named<Enum>, N>& table, Enum value) {
    for (const Named<Enum>& row : table)
        if (row.value == value) return row.name;
    return {};
}

// The value `name` names in `table`; none for any other word.
template <typename Enum, std::size_t N>
constexpr std::optional<Enum> value_in(const std::array<Named<Enum>, N>& table, std::string_view name) {
    for (const Named<Enum>& row : table)
        if (row.name == name) return row.value;
    return std::nullopt;
}

// Every name of `table`, in its order (for a command line's choices).
template <typename Enum, std::size_t N>
std::vector<std::string> names_in(const std::array<Named<Enum>, N>& table) {
    std::vector<std::string> names;
    for (const Named<Enum>& row : table) names.emplace_back(row.name);
    return names;
}

// "global or direct": the choices, for messages.
template <typename Enum, std::size_t N>
std::string choices_in(const std::array<Named<Enum>, N>& table) {
    std::string text;
    for (std::size_t i = 0; i < N; ++i)
        text += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(table[i].name);
    return text;
}

}  // namespace orb::device

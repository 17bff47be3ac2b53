#include "atoms_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "default_lights.h"
#include "orb/scene/detail/json_text.h"
#include "line_reader.h"
#include "orb/scene/auto_framing.h"
#include "orb/scene/error.h"
#include "ply_scene.h"
#include "srgb.h"

namespace orb::molecular {
namespace {

// The grey of atoms that have neither an element nor a type, and of the cell.
constexpr double kPlainGrey = 0.8;
constexpr double kCellGrey = 0.35;
// The cell's spheres: this fraction of the first frame's median atom radius,
// their centres this many of their radii apart along each edge.
constexpr double kCellRadiusFraction = 0.2;
constexpr double kCellSpacingRadii = 3.0;
constexpr std::size_t kMaxCellSpheresPerEdge = 10000;

double atom_radius(const AtomFrame& frame, std::size_t i, const MolecularImportOptions& options,
                   const FrameView& view) {
    if (options.radius == AtomRadius::Fixed) return options.fixed_radius;
    if (!frame.radii.empty()) return frame.radii[i];
    if (frame.elements.empty()) return view.default_radius * options.radius_scale;
    const Element& element = *frame.elements[i];
    return (options.radius == AtomRadius::Covalent ? element.covalent_radius : element.vdw_radius) *
           options.radius_scale;
}

// The spheres along the cell's 12 edges: the 8 corners once, then each
// edge's inner points.
void add_cell(Scene& scene, const Cell& cell, double radius, std::uint32_t material) {
    const auto corner = [&cell](int i, int j, int k) {
        Vec3 p = cell.origin;
        for (int c = 0; c < 3; ++c) p[c] += i * cell.a[c] + j * cell.b[c] + k * cell.c[c];
        return p;
    };
    const auto add = [&](const Vec3& p) {
        Sphere sphere;
        sphere.center = p;
        sphere.radius = radius;
        sphere.material = material;
        scene.spheres.push_back(sphere);
    };
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) add(corner(i, j, k));
    const Vec3* axes[] = {&cell.a, &cell.b, &cell.c};
    for (int axis = 0; axis < 3; ++axis) {
        const Vec3& edge = *axes[axis];
        const double length = std::hypot(edge[0], edge[1], edge[2]);
        const double wanted = std::ceil(length / (kCellSpacingRadii * radius));  // inf or NaN for absurd cells
        const std::size_t steps = wanted >= 0 && wanted < static_cast<double>(kMaxCellSpheresPerEdge)
                                      ? static_cast<std::size_t>(wanted)
                                      : (wanted >= 0 ? kMaxCellSpheresPerEdge : 0);
        for (int u = 0; u < 2; ++u)
            for (int v = 0; v < 2; ++v) {
                // The edge's start: the corner with this axis at 0 and the other two at u, v.
                int ijk[3];
                ijk[axis] = 0;
                ijk[(axis + 1) % 3] = u;
                ijk[(axis + 2) % 3] = v;
                const Vec3 start = corner(ijk[0], ijk[1], ijk[2]);
                for (std::size_t s = 1; s < steps; ++s) {
                    const double t = static_cast<double>(s) / static_cast<double>(steps);
                    add({start[0] + t * edge[0], start[1] + t * edge[1], start[2] + t * edge[2]});
                }
            }
    }
}

double median_radius(const std::vector<Sphere>& spheres) {
    std::vector<double> radii(spheres.size());
    for (std::size_t i = 0; i < spheres.size(); ++i) radii[i] = spheres[i].radius;
    const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), middle, radii.end());
    return *middle;
}

// As the PLY importer looks at a cloud: from above the +z side, 30 degrees
// up, by the framing rule every importer shares (orb/scene/auto_framing.h).
void fix_camera(Scene& scene, FrameView& view, const std::string& source) {
    constexpr double kElevation = 30.0 * std::numbers::pi / 180.0;
    const FramingView framing_view{{0.0, std::sin(kElevation), std::cos(kElevation)}, {0, 1, 0},
                                   scene.camera.vfov_deg, scene.render.width, scene.render.height};
    const Framing framing = *frame_spheres(scene.spheres, framing_view);
    const Vec3& center = framing.target;
    const Vec3& p = framing.position;
    if (std::hypot(p[0] - center[0], p[1] - center[1], p[2] - center[2]) < 0.5 * framing.distance)
        throw InputError(source + ": the atoms lie too far from the origin for their extent (around " +
                         detail::format_number(center[0]) + ", " + detail::format_number(center[1]) + ", " +
                         detail::format_number(center[2]) + "): no camera can be placed in double precision");
    view.camera = scene.camera;
    view.camera.position = framing.position;
    view.camera.target = center;
    view.camera.up = {0, 1, 0};
    view.camera.focus_distance = framing.distance;
    const double diagonal = std::hypot(framing.hi[0] - framing.lo[0], framing.hi[1] - framing.lo[1],
                                       framing.hi[2] - framing.lo[2]);
    view.light_center = center;
    view.light_radius = std::max(diagonal / 2, median_radius(scene.spheres));
}

// The spheres after the atoms (cell, lights) are not atoms: they have no
// value of any property, so colouring or sizing by one leaves them as they are.
void pad_properties(std::vector<SphereProperty>& properties, std::size_t spheres) {
    for (SphereProperty& property : properties) property.values.resize(spheres, kNoValue);
}

}  // namespace

Vec3 type_color(std::size_t type_index) {
    static constexpr unsigned char kOkabeIto[][3] = {{0xE6, 0x9F, 0x00}, {0x56, 0xB4, 0xE9}, {0x00, 0x9E, 0x73},
                                                     {0xF0, 0xE4, 0x42}, {0x00, 0x72, 0xB2}, {0xD5, 0x5E, 0x00},
                                                     {0xCC, 0x79, 0xA7}};
    const unsigned char* rgb = kOkabeIto[type_index % std::size(kOkabeIto)];
    return {detail::srgb_to_linear(rgb[0] / 255.0), detail::srgb_to_linear(rgb[1] / 255.0),
            detail::srgb_to_linear(rgb[2] / 255.0)};
}

Scene atoms_scene(AtomFrame frame, const MolecularImportOptions& options, FrameView& view, const std::string& source) {
    const std::size_t atoms = frame.positions.size();
    if (!view.set && atoms == 0) throw InputError(source + ": frame 1 has no atoms");
    if (!view.set && frame.elements.empty() && frame.radii.empty())
        view.default_radius = ply::default_point_radius(frame.positions);

    Scene scene;
    Material atom;
    atom.name = "atom";
    atom.color = {kPlainGrey, kPlainGrey, kPlainGrey};  // each atom's colour replaces it
    scene.materials.push_back(atom);

    // Atoms without an element are coloured by their type, when the file has
    // one: type n (a whole number, as LAMMPS writes them) by colour n - 1, so a
    // type keeps its colour in every frame whatever order its atoms come in.
    const SphereProperty* type = nullptr;
    std::vector<Vec3> label_colors;
    if (frame.elements.empty())
        for (const SphereProperty& property : frame.properties)
            if (property.name == "type" && property.categorical()) type = &property;
    if (type)
        for (std::size_t k = 0; k < type->labels.size(); ++k) {
            long long number = 0;
            const bool numbered = parse_long(type->labels[k], number) && number >= 1;
            label_colors.push_back(type_color(numbered ? static_cast<std::size_t>(number - 1) : k));
        }

    scene.spheres.resize(atoms);
    std::vector<float>& colors = scene.sphere_attributes.colors;
    colors.reserve(3 * (atoms + 2));
    for (std::size_t i = 0; i < atoms; ++i) {
        Sphere& sphere = scene.spheres[i];
        sphere.center = frame.positions[i];
        sphere.radius = atom_radius(frame, i, options, view);
        const Vec3 color = !frame.elements.empty() ? element_color(*frame.elements[i])
                           : type ? label_colors[static_cast<std::size_t>(type->values[i])]
                                  : Vec3{kPlainGrey, kPlainGrey, kPlainGrey};
        for (double c : color) colors.push_back(static_cast<float>(c));
    }
    frame.positions = {};

    if (options.cell && frame.cell) {
        if (!view.set) view.cell_radius = kCellRadiusFraction * median_radius(scene.spheres);
        Material cell;
        cell.name = "cell";
        cell.color = {kCellGrey, kCellGrey, kCellGrey};
        scene.materials.push_back(cell);
        add_cell(scene, *frame.cell, view.cell_radius, static_cast<std::uint32_t>(scene.materials.size() - 1));
        colors.resize(3 * scene.spheres.size(), static_cast<float>(kCellGrey));
    }

    if (!view.set) {
        fix_camera(scene, view, source);
        view.set = true;
    }
    scene.camera = view.camera;
    detail::add_default_lights(scene, view.light_center, view.light_radius);
    colors.resize(3 * scene.spheres.size(), 0.0f);  // the lights' colour: their material is black and emits

    pad_properties(frame.properties, scene.spheres.size());
    scene.sphere_attributes.properties = std::move(frame.properties);
    return scene;
}

}  // namespace orb::molecular

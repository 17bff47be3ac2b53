// The .scn grammar (docs/scn-format.md):
//   camera ox oy oz  tx ty tz
//   size N
//   N lines: sphere radius  px py pz  er eg eb  cr cg cb  m
// One statement per line, in this order; blank lines anywhere.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"
#include "orb/import/scn.h"
#include "scn_names.h"
#include "scn_text.h"

namespace orb {
namespace {

using scn::Line;
using scn::Word;

constexpr std::string_view kCameraSyntax = "'camera ox oy oz  tx ty tz'";
constexpr std::string_view kSizeSyntax = "'size N'";
constexpr std::string_view kSphereSyntax = "'sphere radius  px py pz  er eg eb  cr cg cb  m'";

// Material indices are 32-bit in the scene model, so that bounds the sphere count too.
constexpr std::uint64_t kMaxSpheres = std::numeric_limits<std::uint32_t>::max();

class ScnParser {
public:
    ScnParser(std::string_view text, int column_offset, const std::string& source)
        : lines_(text, column_offset), source_(source) {}

    Scene parse() {
        Line line;
        if (!lines_.next(line))
            throw_at(source_, lines_.end_line(), lines_.end_column(),
                     "expected " + std::string(kCameraSyntax) + ", got an empty file");
        read_camera(line);
        if (!lines_.next(line))
            throw_at(source_, lines_.end_line(), lines_.end_column(),
                     "expected " + std::string(kSizeSyntax) + " after the camera, got end of file");
        const std::uint64_t declared = read_size(line);
        while (lines_.next(line)) read_sphere(line, declared);
        if (scene_.spheres.size() != declared)
            throw_at(source_, size_word_.line, size_word_.column,
                     "expected " + std::to_string(declared) + " sphere lines after 'size " +
                         std::string(size_word_.text) + "', found " + std::to_string(scene_.spheres.size()) +
                         " before the end of file");
        return std::move(scene_);
    }

private:
    // Word i of the line, or an error at the end of the line naming what was expected.
    const Word& field(const Line& line, size_t i, std::string_view what) {
        if (i >= line.words.size())
            throw_at(source_, line.number, line.end_column, "expected " + std::string(what) + ", got end of line");
        return line.words[i];
    }

    double number(const Line& line, size_t i, std::string_view what) {
        return scn::parse_number(field(line, i, what), source_, what);
    }

    Vec3 vector(const Line& line, size_t first, std::string_view what) {
        const std::string name(what);
        return {number(line, first, name + " x"), number(line, first + 1, name + " y"),
                number(line, first + 2, name + " z")};
    }

    void expect_line_end(const Line& line, size_t count, std::string_view after) {
        if (line.words.size() > count) {
            const Word& extra = line.words[count];
            throw_at(source_, extra.line, extra.column,
                     "expected end of line after " + std::string(after) + ", got " + scn::quoted_word(extra.text));
        }
    }

    void expect_keyword(const Line& line, std::string_view keyword, std::string_view syntax) {
        const Word& word = line.words.front();
        if (word.text == keyword) return;
        std::string message = "expected " + std::string(syntax) + ", got " + scn::quoted_word(word.text);
        if (keyword == "camera" && (word.text == "size" || word.text == "sphere"))
            message = "missing camera: expected " + std::string(syntax) + " before " + scn::quoted_word(word.text);
        throw_at(source_, word.line, word.column, message);
    }

    void read_camera(const Line& line) {
        expect_keyword(line, "camera", kCameraSyntax);
        Camera& camera = scene_.camera;
        camera.position = vector(line, 1, "camera position");
        camera.target = vector(line, 4, "camera target");
        expect_line_end(line, 7, "the camera target");
        // SmallptGPU's framing: +y up and an image plane pi/4 high at unit distance.
        camera.up = {0.0, 1.0, 0.0};
        camera.vfov_deg = smallptgpu_vfov_deg();
        check_camera(line);
    }

    // The view direction must exist and must not be parallel to +y, or there is no image plane.
    void check_camera(const Line& line) {
        const Camera& camera = scene_.camera;
        const Vec3 d{camera.target[0] - camera.position[0], camera.target[1] - camera.position[1],
                     camera.target[2] - camera.position[2]};
        const Word& target = line.words[4];
        const double length = std::hypot(d[0], d[1], d[2]);  // hypot: no overflow for huge coordinates
        if (!(length > 0.0) || !std::isfinite(length))
            throw_at(source_, target.line, target.column,
                     "expected a camera target different from the camera position (degenerate camera)");
        // |d x up| / |d| is the sine of the angle between the view and +y.
        const double sine = std::hypot(d[0], d[2]) / length;
        if (!(sine > 1e-9))
            throw_at(source_, target.line, target.column,
                     "expected a view direction not parallel to the +y up vector (degenerate camera)");
    }

    std::uint64_t read_size(const Line& line) {
        expect_keyword(line, "size", kSizeSyntax);
        size_word_ = field(line, 1, "the sphere count");
        const std::uint64_t count = scn::parse_count(size_word_, source_, "the sphere count", kMaxSpheres);
        expect_line_end(line, 2, "the sphere count");
        // No reserve(count): an absurd size must not allocate before its lines exist.
        return count;
    }

    void read_sphere(const Line& line, std::uint64_t declared) {
        const Word& keyword = line.words.front();
        if (keyword.text == "sphere" && scene_.spheres.size() >= declared)
            throw_at(source_, keyword.line, keyword.column,
                     "expected end of file: 'size " + std::string(size_word_.text) + "' on line " +
                         std::to_string(size_word_.line) + " declares " + std::to_string(declared) +
                         " spheres, this is one more");
        if (keyword.text == "camera" || keyword.text == "size")
            throw_at(source_, keyword.line, keyword.column,
                     "expected " + std::string(kSphereSyntax) + ", got a second " + scn::quoted_word(keyword.text) +
                         " statement");
        expect_keyword(line, "sphere", kSphereSyntax);

        Sphere sphere;
        sphere.radius = number(line, 1, "the radius");
        if (!(sphere.radius > 0.0))
            throw_at(source_, line.words[1].line, line.words[1].column,
                     "expected a radius > 0, got " + scn::quoted_word(line.words[1].text));
        sphere.center = vector(line, 2, "the centre");
        Material material;
        material.emission = colour(line, 5, "emission", false);
        material.color = colour(line, 8, "colour", true);
        material.type = material_type(field(line, 11, "the material code (0 diffuse, 1 mirror, 2 glass)"));
        expect_line_end(line, 12, "the material code");

        sphere.material = material_index(material);
        sphere.name = scn::sphere_name(scene_.spheres.size());
        scene_.spheres.push_back(std::move(sphere));
    }

    // Emission is radiance (>= 0, unbounded); colour is a reflectance in [0, 1].
    Vec3 colour(const Line& line, size_t first, std::string_view what, bool at_most_one) {
        static constexpr std::array<const char*, 3> kChannels{" r", " g", " b"};
        Vec3 value{};
        for (size_t c = 0; c < 3; ++c) {
            const std::string name = std::string(what) + kChannels[c];
            value[c] = number(line, first + c, name);
            const bool in_range = value[c] >= 0.0 && (!at_most_one || value[c] <= 1.0);
            if (!in_range) {
                const Word& word = line.words[first + c];
                throw_at(source_, word.line, word.column,
                         "expected " + name + (at_most_one ? " in [0, 1]" : " >= 0") + ", got " +
                             scn::quoted_word(word.text));
            }
        }
        return value;
    }

    MaterialType material_type(const Word& word) {
        if (word.text == "0") return MaterialType::Diffuse;
        if (word.text == "1") return MaterialType::Mirror;
        if (word.text == "2") return MaterialType::Dielectric;
        throw_at(source_, word.line, word.column,
                 "expected material code 0 (diffuse), 1 (mirror) or 2 (glass), got " + scn::quoted_word(word.text));
    }

    // One material per distinct (type, colour, emission): spheres that look alike share it.
    std::uint32_t material_index(Material material) {
        const MaterialKey key = material_key(material);
        const auto found = material_by_key_.find(key);
        if (found != material_by_key_.end()) return found->second;

        material.ior = 1.5;  // SmallptGPU's glass
        const std::string base = scn::describe_material(material);
        std::string name = base;
        for (int n = 2; used_names_.count(name) != 0; ++n) name = base + " " + std::to_string(n);
        used_names_[name] = true;
        material.name = std::move(name);

        const auto index = static_cast<std::uint32_t>(scene_.materials.size());
        scene_.materials.push_back(std::move(material));
        material_by_key_.emplace(key, index);
        return index;
    }

    scn::LineReader lines_;
    const std::string& source_;
    Scene scene_;
    Word size_word_;
    // Keyed on bit patterns so -0 and 0 stay distinct and every number round-trips exactly.
    using MaterialKey = std::array<std::uint64_t, 7>;
    static MaterialKey material_key(const Material& m) {
        return {static_cast<std::uint64_t>(m.type),   std::bit_cast<std::uint64_t>(m.color[0]),
                std::bit_cast<std::uint64_t>(m.color[1]), std::bit_cast<std::uint64_t>(m.color[2]),
                std::bit_cast<std::uint64_t>(m.emission[0]), std::bit_cast<std::uint64_t>(m.emission[1]),
                std::bit_cast<std::uint64_t>(m.emission[2])};
    }
    std::map<MaterialKey, std::uint32_t> material_by_key_;
    std::map<std::string, bool> used_names_;
};

}  // namespace

Scene parse_scn(std::string_view text, const std::string& source) {
    const std::string_view body = scn::require_text(text, source);
    const int column_offset = static_cast<int>(text.size() - body.size());  // a skipped byte-order mark
    Scene scene = ScnParser(body, column_offset, source).parse();
    // The checks every importer shares (finite values, ranges, references).
    validate_scene(scene, source);
    return scene;
}

}  // namespace orb

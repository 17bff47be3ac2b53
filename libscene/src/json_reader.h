// Reading JSON with the path of every problem in the message: the shared
// reader behind the scene loader and its animation section.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>

namespace orb::detail {

class JsonReader {
public:
    using json = nlohmann::json;

    explicit JsonReader(std::string source) : source_(std::move(source)) {}

    // Throws InputError("source: path: message").
    [[noreturn]] void fail(const std::string& path, const std::string& message) const;

    const json& member(const json& object, const std::string& path, const char* key) const;
    // Rejects keys not in `allowed`, naming the ones that are.
    void only_keys(const json& object, const std::string& path, std::initializer_list<const char*> allowed) const;

    const json& object(const json& value, const std::string& path) const;
    const json& array(const json& value, const std::string& path) const;
    double number(const json& value, const std::string& path) const;  // finite
    // A whole number (640 or 640.0) within [lo, hi].
    std::int64_t integer(const json& value, const std::string& path, std::int64_t lo = -(std::int64_t(1) << 53),
                         std::int64_t hi = std::int64_t(1) << 53) const;
    std::string string(const json& value, const std::string& path) const;

    template <std::size_t N>
    std::array<double, N> numbers(const json& value, const std::string& path) const {
        if (!value.is_array() || value.size() != N)
            fail(path, "expected an array of " + std::to_string(N) + " numbers, got " + describe(value));
        std::array<double, N> result{};
        for (std::size_t i = 0; i < N; ++i) result[i] = number(value[i], index(path, i));
        return result;
    }

    static std::string join(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }
    static std::string index(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }
    // "number 12", "string \"abc\"" (shortened): what was found, for messages.
    static std::string describe(const json& value);

    const std::string& source() const { return source_; }

private:
    std::string source_;
};

}  // namespace orb::detail

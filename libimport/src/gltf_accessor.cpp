// Reading glTF accessors without trusting a single offset: tinygltf parses
// the JSON but does not check that accessors stay inside their buffers.
#include <cmath>
#include <cstring>
#include <limits>

#include "gltf_internal.h"

namespace orb::gltf {
namespace {

// Accessors without a buffer view (all zeros, maybe sparse) allocate memory
// for `count` elements with no data to back it; cap them.
constexpr std::uint64_t kMaxUnbackedElements = std::uint64_t(1) << 20;

int component_size(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

int component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        default: return 0;  // matrices are not needed by the importer
    }
}

const char* type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "an unknown type";
    }
}

// One component, converted per the glTF rules for normalised integers.
double decode(const unsigned char* p, int component_type, bool normalized) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const auto v = static_cast<std::int8_t>(*p);
            return normalized ? std::fmax(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0 : *p;
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::fmax(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_INT: {
            std::int32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return normalized ? v / 4294967295.0 : v;
        }
        default: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
    }
}

// Start of `count` elements of `element_size` bytes, `stride` apart, in
// buffer view `view_index` at `offset`; fails unless all of them fit.
const unsigned char* checked_span(const tinygltf::Model& model, int view_index, std::uint64_t offset,
                                  std::uint64_t count, std::uint64_t element_size, std::uint64_t stride,
                                  const std::string& what, const Diagnostics& diagnostics) {
    if (view_index < 0 || std::size_t(view_index) >= model.bufferViews.size())
        diagnostics.fail(what + ": bufferView " + std::to_string(view_index) + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(view_index)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
        diagnostics.fail(what + ": bufferView " + std::to_string(view_index) + " names buffer " +
                         std::to_string(view.buffer) + ", which does not exist");
    const tinygltf::Buffer& buffer = model.buffers[std::size_t(view.buffer)];
    const std::uint64_t view_offset = view.byteOffset, view_length = view.byteLength;
    if (view_offset > buffer.data.size() || view_length > buffer.data.size() - view_offset)
        diagnostics.fail(what + ": bufferView " + std::to_string(view_index) + " (bytes " + std::to_string(view_offset) +
                         " + " + std::to_string(view_length) + ") runs past the end of buffer " +
                         std::to_string(view.buffer) + " (" + std::to_string(buffer.data.size()) + " bytes)");
    if (count == 0) return buffer.data.data() + view_offset;
    // count <= 2^32 and stride, offset <= 2^32 keep these products inside 64 bits.
    if (count > std::numeric_limits<std::uint32_t>::max() || stride > std::numeric_limits<std::uint32_t>::max() ||
        offset > view_length)
        diagnostics.fail(what + ": accessor offset " + std::to_string(offset) + " is outside its bufferView (" +
                         std::to_string(view_length) + " bytes)");
    const std::uint64_t end = offset + (count - 1) * stride + element_size;
    if (end > view_length)
        diagnostics.fail(what + ": " + std::to_string(count) + " elements need " + std::to_string(end) +
                         " bytes of bufferView " + std::to_string(view_index) + ", which has " +
                         std::to_string(view_length));
    return buffer.data.data() + view_offset + offset;
}

}  // namespace

AccessorValues read_accessor(const tinygltf::Model& model, int index, std::initializer_list<int> allowed_types,
                             const std::string& what, const Diagnostics& diagnostics) {
    if (index < 0 || std::size_t(index) >= model.accessors.size())
        diagnostics.fail(what + ": accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
    const std::string name = what + " (accessor " + std::to_string(index) + ")";
    bool type_ok = false;
    std::string expected;
    for (int type : allowed_types) {
        type_ok = type_ok || accessor.type == type;
        expected += std::string(expected.empty() ? "" : " or ") + type_name(type);
    }
    if (!type_ok) diagnostics.fail(name + ": expected " + expected + ", got " + type_name(accessor.type));
    const int size = component_size(accessor.componentType);
    if (size == 0) diagnostics.fail(name + ": unknown componentType " + std::to_string(accessor.componentType));

    AccessorValues result;
    result.components = component_count(accessor.type);
    result.count = accessor.count;
    const std::uint64_t element_size = std::uint64_t(size) * std::uint64_t(result.components);

    if (accessor.bufferView >= 0) {
        const tinygltf::BufferView* view = std::size_t(accessor.bufferView) < model.bufferViews.size()
                                               ? &model.bufferViews[std::size_t(accessor.bufferView)]
                                               : nullptr;
        const std::uint64_t stride = view && view->byteStride != 0 ? view->byteStride : element_size;
        if (view && view->byteStride != 0 && (view->byteStride < element_size || view->byteStride > 252))
            diagnostics.fail(name + ": byteStride " + std::to_string(view->byteStride) + " is invalid for " +
                             std::to_string(element_size) + "-byte elements");
        const unsigned char* data = checked_span(model, accessor.bufferView, accessor.byteOffset, result.count,
                                                 element_size, stride, name, diagnostics);
        result.values.resize(result.count * std::size_t(result.components));
        for (std::size_t i = 0; i < result.count; ++i)
            for (int c = 0; c < result.components; ++c)
                result.values[i * std::size_t(result.components) + std::size_t(c)] =
                    decode(data + i * stride + std::size_t(c * size), accessor.componentType, accessor.normalized);
    } else {
        if (result.count > kMaxUnbackedElements)
            diagnostics.fail(name + ": " + std::to_string(result.count) + " elements without a bufferView");
        result.values.assign(result.count * std::size_t(result.components), 0.0);
    }

    if (accessor.sparse.isSparse) {
        const auto& sparse = accessor.sparse;
        if (sparse.count < 1 || std::uint64_t(sparse.count) > result.count)
            diagnostics.fail(name + ": sparse.count " + std::to_string(sparse.count) + " must be in [1, " +
                             std::to_string(result.count) + "]");
        const int index_size = component_size(sparse.indices.componentType);
        if (index_size == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
            sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
            sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_INT ||
            sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
            diagnostics.fail(name + ": sparse.indices.componentType must be an unsigned integer type");
        if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
            diagnostics.fail(name + ": sparse byteOffset must be >= 0");
        const unsigned char* indices =
            checked_span(model, sparse.indices.bufferView, std::uint64_t(sparse.indices.byteOffset),
                         std::uint64_t(sparse.count), std::uint64_t(index_size), std::uint64_t(index_size),
                         name + " sparse indices", diagnostics);
        const unsigned char* values =
            checked_span(model, sparse.values.bufferView, std::uint64_t(sparse.values.byteOffset),
                         std::uint64_t(sparse.count), element_size, element_size, name + " sparse values", diagnostics);
        for (std::size_t k = 0; k < std::size_t(sparse.count); ++k) {
            const double target = decode(indices + k * std::size_t(index_size), sparse.indices.componentType, false);
            if (!(target >= 0) || target >= double(result.count))
                diagnostics.fail(name + ": sparse index " + std::to_string(std::uint64_t(target)) +
                                 " is out of range (count " + std::to_string(result.count) + ")");
            const std::size_t i = std::size_t(target);
            for (int c = 0; c < result.components; ++c)
                result.values[i * std::size_t(result.components) + std::size_t(c)] =
                    decode(values + k * element_size + std::size_t(c * size), accessor.componentType,
                           accessor.normalized);
        }
    }
    for (double v : result.values)
        if (!std::isfinite(v)) diagnostics.fail(name + ": contains a value that is not finite");
    return result;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                        std::size_t vertex_count, const std::string& what,
                                        const Diagnostics& diagnostics) {
    std::vector<std::uint32_t> indices;
    if (primitive.indices < 0) {
        if (vertex_count > std::numeric_limits<std::uint32_t>::max())
            diagnostics.fail(what + ": too many vertices");
        indices.resize(vertex_count);
        for (std::size_t i = 0; i < vertex_count; ++i) indices[i] = std::uint32_t(i);
        return indices;
    }
    const AccessorValues values =
        read_accessor(model, primitive.indices, {TINYGLTF_TYPE_SCALAR}, what + " indices", diagnostics);
    indices.reserve(values.count);
    for (double v : values.values) {
        if (!(v >= 0) || v >= double(vertex_count) || v != std::floor(v))
            diagnostics.fail(what + ": vertex index " + std::to_string(v) + " is out of range (" +
                             std::to_string(vertex_count) + " vertices)");
        indices.push_back(std::uint32_t(v));
    }
    return indices;
}

}  // namespace orb::gltf

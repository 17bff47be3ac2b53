#include "exr_scanline_writer.h"

#include <OpenEXR/openexr.h>

#include <Imath/half.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>

#include "block_workers.h"
#include "exr_zip_block.h"

namespace orb::exr::detail {
namespace {

static_assert(std::endian::native == std::endian::little, "EXR blocks are little-endian, as this writer's values");

// The file, written by OpenEXR's core library through this sink: at any
// offset (it writes the offset table last, behind the header).
struct MemorySink {
    std::string& bytes;
    std::size_t& size;
};

int64_t write_to_memory(exr_const_context_t, void* user, const void* buffer, uint64_t count, uint64_t offset,
                        exr_stream_error_func_ptr_t) {
    auto& sink = *static_cast<MemorySink*>(user);
    const std::uint64_t end = offset + count;
    if (end > sink.bytes.size()) sink.bytes.resize(std::max<std::uint64_t>(end, 2 * sink.bytes.size()));
    std::memcpy(sink.bytes.data() + offset, buffer, count);
    sink.size = std::max<std::size_t>(sink.size, end);
    return static_cast<int64_t>(count);
}

// The core library reports through a callback; the first message is kept for the exception.
thread_local std::string last_core_error;
void keep_error(exr_const_context_t, exr_result_t code, const char* message) {
    if (last_core_error.empty())
        last_core_error = std::string(exr_get_error_code_as_string(code)) + (message ? std::string(": ") + message : "");
}

void check(exr_result_t result, const char* what) {
    if (result == EXR_ERR_SUCCESS) return;
    const std::string detail = last_core_error.empty() ? exr_get_error_code_as_string(result) : last_core_error;
    last_core_error.clear();
    throw std::runtime_error(std::string("cannot encode the EXR (") + what + "): " + detail);
}

// Closes the context however encoding ends.
struct WriteContext {
    exr_context_t context = nullptr;
    ~WriteContext() {
        if (context) exr_finish(&context);
    }
};

exr_compression_t to_core(ExrCompression compression) {
    switch (compression) {
        case ExrCompression::None: return EXR_COMPRESSION_NONE;
        case ExrCompression::Zips: return EXR_COMPRESSION_ZIPS;
        case ExrCompression::Zip: return EXR_COMPRESSION_ZIP;
        default: throw std::logic_error("the scanline writer writes no RLE or PIZ");
    }
}

void add_attributes(exr_context_t context, const std::vector<HeaderAttribute>& attributes) {
    for (const HeaderAttribute& a : attributes) {
        const char* name = a.name.c_str();
        if (const int* value = std::get_if<int>(&a.value)) {
            check(exr_attr_set_int(context, 0, name, *value), name);
        } else if (const double* value = std::get_if<double>(&a.value)) {
            check(exr_attr_set_double(context, 0, name, *value), name);
        } else if (const std::string* value = std::get_if<std::string>(&a.value)) {
            check(exr_attr_set_string(context, 0, name, value->c_str()), name);
        } else {
            const Matrix44& m = std::get<Matrix44>(a.value);
            exr_attr_m44f_t matrix{};
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) matrix.m[4 * i + j] = m[i][j];
            check(exr_attr_set_m44f(context, 0, name, &matrix), name);
        }
    }
}

struct Channel {
    const Plane* plane;
    bool half;
};

// Within a block, OpenEXR stores each scanline's channels one after another,
// in the channel list's order (sorted by name), each a row of values: 4
// bytes a value for FLOAT and UINT (whose bits an exact-sum plane holds),
// 2 for HALF.
void pack_block(const std::vector<Channel>& channels, int width, int first_row, int rows,
                std::vector<std::uint8_t>& out) {
    std::size_t bytes_per_row = 0;
    for (const Channel& c : channels) bytes_per_row += static_cast<std::size_t>(width) * (c.half ? 2 : 4);
    out.resize(bytes_per_row * static_cast<std::size_t>(rows));
    std::uint8_t* at = out.data();
    for (int y = first_row; y < first_row + rows; ++y)
        for (const Channel& c : channels) {
            const float* row = c.plane->values.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
            if (c.half) {
                for (int x = 0; x < width; ++x) {
                    const std::uint16_t bits = Imath::half(row[x]).bits();
                    std::memcpy(at, &bits, 2);
                    at += 2;
                }
            } else {
                std::memcpy(at, row, static_cast<std::size_t>(width) * 4);
                at += static_cast<std::size_t>(width) * 4;
            }
        }
}

// Runs job(block, compressor, raw) for every block on the shared block
// workers; rethrows the first error. Each thread keeps its compressor and
// its packing memory from block to block and from file to file.
template <typename Job>
void for_each_block(int blocks, Job job) {
    run_blocks(blocks, [&](int block) {
        thread_local ZipBlockCompressor compressor;
        thread_local std::vector<std::uint8_t> raw;
        job(block, compressor, raw);
    });
}

}  // namespace

bool scanline_writer_handles(ExrCompression compression) {
    return compression == ExrCompression::None || compression == ExrCompression::Zips ||
           compression == ExrCompression::Zip;
}

void write_scanline_exr(const Film& film, const PlaneSet& set, const std::vector<Plane>& planes,
                        bool filled, bool half, ExrCompression compression, const std::vector<HeaderAttribute>& attributes,
                        ScanlineBuffers& buffers, std::string& bytes, std::size_t& size) {
    size = 0;
    last_core_error.clear();
    MemorySink sink{bytes, size};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &sink;
    init.write_fn = write_to_memory;
    init.error_handler_fn = keep_error;
    WriteContext write;
    check(exr_start_write(&write.context, "<memory>", EXR_WRITE_FILE_DIRECTLY, &init), "start");
    exr_context_t context = write.context;
    int part = 0;
    check(exr_add_part(context, "", EXR_STORAGE_SCANLINE, &part), "part");
    check(exr_initialize_required_attr_simple(context, part, film.width, film.height, to_core(compression)),
          "required attributes");

    std::vector<Channel> channels;
    for (const Plane& plane : planes) channels.push_back({&plane, half && !plane.always_float});
    std::sort(channels.begin(), channels.end(),
              [](const Channel& a, const Channel& b) { return a.plane->name < b.plane->name; });
    for (const Channel& c : channels) {
        const exr_pixel_type_t type = c.plane->exact_sum ? EXR_PIXEL_UINT : c.half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT;
        const exr_perceptual_treatment_t treatment =
            c.plane->exact_sum ? EXR_PERCEPTUALLY_LINEAR : EXR_PERCEPTUALLY_LOGARITHMIC;
        if (exr_add_channel(context, part, c.plane->name.c_str(), type, treatment, 1, 1) < 0)
            check(EXR_ERR_INVALID_ARGUMENT, c.plane->name.c_str());
    }
    add_attributes(context, attributes);
    check(exr_write_header(context), "header");

    int32_t rows_per_block = 0;
    check(exr_get_scanlines_per_chunk(context, part, &rows_per_block), "block size");
    const int blocks = (film.height + rows_per_block - 1) / rows_per_block;
    buffers.blocks.resize(static_cast<std::size_t>(blocks));
    const auto width = static_cast<std::size_t>(film.width);
    for_each_block(blocks, [&](int block, ZipBlockCompressor& compressor, std::vector<std::uint8_t>& raw) {
        const int first_row = block * rows_per_block;
        const int rows = std::min(rows_per_block, film.height - first_row);
        if (!filled)
            fill_planes(film, set, planes, static_cast<std::size_t>(first_row) * width,
                        static_cast<std::size_t>(first_row + rows) * width);
        std::vector<std::uint8_t>& stored = buffers.blocks[static_cast<std::size_t>(block)];
        if (compression == ExrCompression::None) {
            pack_block(channels, film.width, first_row, rows, stored);
            return;
        }
        pack_block(channels, film.width, first_row, rows, raw);
        if (!compressor.compress(raw, stored)) stored.swap(raw);
    });
    for (int block = 0; block < blocks; ++block) {
        const std::vector<std::uint8_t>& stored = buffers.blocks[static_cast<std::size_t>(block)];
        check(exr_write_scanline_chunk(context, part, block * rows_per_block, stored.data(), stored.size()), "block");
    }
    const exr_result_t finished = exr_finish(&write.context);
    write.context = nullptr;
    check(finished, "finish");
}

}  // namespace orb::exr::detail

// The part of Intel Open Image Denoise's C API (version 2) that Orb calls,
// declared here from the API's documentation (the "Open Image Denoise API"
// chapter of the OIDN manual): Orb loads libOpenImageDenoise.so.2 at run time
// and builds without OIDN's headers (docs/design/denoising-with-oidn.md).
// Only the handle types, the enumerator values Orb uses and the signatures
// of the entry points in OidnApi below; the values are part of OIDN 2's
// stable ABI.
#pragma once

#include <cstddef>

namespace orb::denoise::oidn {

// Opaque handles (OIDNDevice, OIDNFilter, OIDNBuffer are pointers to
// incomplete structs in the C API).
struct DeviceImpl;
struct FilterImpl;
struct BufferImpl;
using Device = DeviceImpl*;
using Filter = FilterImpl*;
using Buffer = BufferImpl*;

// OIDNDeviceType
enum DeviceType : int { kDeviceDefault = 0, kDeviceCpu = 1, kDeviceSycl = 2, kDeviceCuda = 3, kDeviceHip = 4, kDeviceMetal = 5 };

// OIDNError
enum Error : int {
    kErrorNone = 0,
    kErrorUnknown = 1,
    kErrorInvalidArgument = 2,
    kErrorInvalidOperation = 3,
    kErrorOutOfMemory = 4,
    kErrorUnsupportedHardware = 5,
    kErrorCancelled = 6,
};

// OIDNFormat: 3 floats per pixel.
enum Format : int { kFormatFloat3 = 3 };

// OIDNStorage: where a buffer lives. Host memory is pinned (page-locked)
// for a GPU device, so copies between it and the device run at the bus's
// speed and asynchronously.
enum Storage : int { kStorageUndefined = 0, kStorageHost = 1, kStorageDevice = 2, kStorageManaged = 3 };

// OIDNQuality
enum Quality : int { kQualityDefault = 0, kQualityFast = 4, kQualityBalanced = 5, kQualityHigh = 6 };

// The entry points, as function pointers filled by dlsym.
struct Api {
    Device (*oidnNewDevice)(DeviceType type);
    void (*oidnSetDeviceInt)(Device device, const char* name, int value);
    int (*oidnGetDeviceInt)(Device device, const char* name);
    void (*oidnCommitDevice)(Device device);
    Error (*oidnGetDeviceError)(Device device, const char** message);
    void (*oidnReleaseDevice)(Device device);

    Buffer (*oidnNewBuffer)(Device device, std::size_t byte_size);
    void (*oidnWriteBuffer)(Buffer buffer, std::size_t byte_offset, std::size_t byte_size, const void* source);
    void (*oidnReadBuffer)(Buffer buffer, std::size_t byte_offset, std::size_t byte_size, void* destination);
    void (*oidnReleaseBuffer)(Buffer buffer);
    Buffer (*oidnNewBufferWithStorage)(Device device, std::size_t byte_size, Storage storage);
    void* (*oidnGetBufferData)(Buffer buffer);
    void (*oidnWriteBufferAsync)(Buffer buffer, std::size_t byte_offset, std::size_t byte_size, const void* source);
    void (*oidnReadBufferAsync)(Buffer buffer, std::size_t byte_offset, std::size_t byte_size, void* destination);
    void (*oidnSyncDevice)(Device device);

    Filter (*oidnNewFilter)(Device device, const char* type);
    void (*oidnSetFilterImage)(Filter filter, const char* name, Buffer buffer, Format format, std::size_t width,
                               std::size_t height, std::size_t byte_offset, std::size_t pixel_byte_stride,
                               std::size_t row_byte_stride);
    void (*oidnSetFilterBool)(Filter filter, const char* name, bool value);
    void (*oidnSetFilterInt)(Filter filter, const char* name, int value);
    void (*oidnCommitFilter)(Filter filter);
    void (*oidnExecuteFilter)(Filter filter);
    void (*oidnExecuteFilterAsync)(Filter filter);
    void (*oidnReleaseFilter)(Filter filter);
};

}  // namespace orb::denoise::oidn

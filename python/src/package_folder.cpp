#include "package_folder.h"

#include <dlfcn.h>

#include <filesystem>

namespace orb::python {

std::string package_folder() {
    // The loader knows which file it mapped this function from: orb/_orb*.so.
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&package_folder), &info) == 0 || !info.dli_fname) return ".";
    return std::filesystem::path(info.dli_fname).parent_path().string();
}

std::string runtime_module_folder() { return (std::filesystem::path(package_folder()) / "lib").string(); }

}  // namespace orb::python

#include "errors.h"

#include <CLI/CLI.hpp>

#include "orb/cli/tool_main.h"
#include "orb/render/device.h"
#include "orb/scene/error.h"

namespace py = pybind11;

namespace orb::python {
namespace {

// A file that is not there: FileNotFoundError, a subclass of OSError.
struct FileNotFound : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace

void throw_value_error(const std::string& message) { throw py::value_error(message); }
void throw_file_not_found(const std::string& message) { throw FileNotFound(message); }

void register_errors(py::module_& module) {
    // Created once with the module and kept for its lifetime (pybind11's own pattern).
    static py::exception<InputError> error(module, "Error", PyExc_RuntimeError);
    error.doc() = "What ends a tool with exit status 1: a scene, file or device Orb cannot use, with the tool's message.";
    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const FileNotFound& e) {
            PyErr_SetString(PyExc_FileNotFoundError, e.what());
        } catch (const InputError& e) {
            PyErr_SetString(error.ptr(), e.what());
        } catch (const render::NoOpenCLError& e) {
            PyErr_SetString(error.ptr(), e.what());
        } catch (const cli::UsageError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const CLI::Error& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const py::builtin_exception&) {
            throw;  // pybind11's own (ValueError, KeyError, TypeError, ...): its translator raises them
        } catch (const py::error_already_set&) {
            throw;  // a Python exception on its way back (KeyboardInterrupt, a callback's)
        } catch (const std::bad_alloc&) {
            throw;  // MemoryError
        } catch (const std::exception& e) {
            // Whatever else a library throws (no such device, a file that
            // cannot be written, an OpenCL failure) ends a tool with its
            // message and exit status 1: here orb.Error, not a bare RuntimeError.
            PyErr_SetString(error.ptr(), e.what());
        }
    });
}

}  // namespace orb::python

#include "numpy_arrays.h"

#include "errors.h"

namespace py = pybind11;

namespace orb::python {

std::string shape_text(const py::array& array) {
    std::string text = "(";
    for (py::ssize_t axis = 0; axis < array.ndim(); ++axis)
        text += (axis > 0 ? ", " : "") + std::to_string(array.shape(axis));
    return text + (array.ndim() == 1 ? ",)" : ")");
}

DoubleRows double_array(const py::handle& value, const std::string& name, long rows, long columns) {
    const py::array array = py::array::ensure(value);
    if (!array) throw_value_error(name + ": expected an array of numbers");
    const char kind = array.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw_value_error(name + ": expected numbers (a float or integer array), got dtype " +
                          std::string(py::str(array.dtype())));
    const std::string wanted = columns > 0 ? "(N, " + std::to_string(columns) + ")" : "(N,)";
    const bool shaped = columns > 0 ? array.ndim() == 2 && array.shape(1) == columns : array.ndim() == 1;
    if (!shaped || (rows >= 0 && array.shape(0) != rows))
        throw_value_error(name + ": expected shape " +
                          (rows >= 0 ? (columns > 0 ? "(" + std::to_string(rows) + ", " + std::to_string(columns) + ")"
                                                    : "(" + std::to_string(rows) + ",)")
                                     : wanted) +
                          ", got " + shape_text(array));
    // numpy's cast and copy (none for a C-contiguous float64 array).
    DoubleRows converted = DoubleRows::ensure(array);
    if (!converted) throw_value_error(name + ": cannot be read as float64 numbers");
    return converted;
}

}  // namespace orb::python

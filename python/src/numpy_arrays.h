// numpy arrays read in C++, whatever their float dtype and strides: one
// conversion by numpy's own C loops (no per-element Python), then plain
// vectors. Shapes and dtypes that cannot be meant raise ValueError naming
// the argument ("centers: expected shape (N, 3), got (4, 2)").
#pragma once

#include <pybind11/numpy.h>

#include <cstddef>
#include <string>

namespace orb::python {

using DoubleRows = pybind11::array_t<double, pybind11::array::c_style>;

// `value` as a C-contiguous float64 array of shape (rows, columns) (columns 0:
// shape (rows,)); rows < 0 takes any count. Accepts numbers only (float and
// integer dtypes, a nested list of them).
DoubleRows double_array(const pybind11::handle& value, const std::string& name, long rows, long columns);

// "(4, 2)": an array's shape as numpy prints it.
std::string shape_text(const pybind11::array& array);

}  // namespace orb::python

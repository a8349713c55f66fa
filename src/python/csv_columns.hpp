#pragma once
// A CSV file that a run wrote (io/csv_writer.hpp: a header of column names, then numbers in their
// shortest exact form) read back as one NumPy array per column. strtod reads each number back to the
// same double, so a Python run's forces and history are the CLI run's, bit for bit.
#include <filesystem>

#include <pybind11/pybind11.h>

namespace mpmcut::python {

// {column name: float64 ndarray}; an empty dict when the file does not exist.
pybind11::dict read_csv_columns(const std::filesystem::path& file);

}  // namespace mpmcut::python

#include "python/csv_columns.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>

namespace py = pybind11;

namespace mpmcut::python {

py::dict read_csv_columns(const std::filesystem::path& file) {
  py::dict out;
  std::ifstream in(file);
  if (!in) return out;
  std::string line;
  std::vector<std::string> names;
  if (std::getline(in, line))
    for (std::stringstream ss(line); std::getline(ss, line, ',');) names.push_back(line);
  std::vector<std::vector<double>> columns(names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const char* p = line.c_str();
    for (std::size_t k = 0; k < names.size(); ++k) {
      char* end = nullptr;
      columns[k].push_back(std::strtod(p, &end));
      if (end == p) throw std::runtime_error(fmt::format("{}: not a number in column '{}'", file.string(), names[k]));
      p = *end == ',' ? end + 1 : end;
    }
  }
  for (std::size_t k = 0; k < names.size(); ++k)
    out[py::str(names[k])] = py::array_t<double>(static_cast<py::ssize_t>(columns[k].size()), columns[k].data());
  return out;
}

}  // namespace mpmcut::python

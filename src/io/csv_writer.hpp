#pragma once
// Time series as CSV: one header line of column names (units in the names, e.g. "time_s",
// "kinetic_energy_J_per_m"), then one line of numbers per row. Numbers are written in the
// shortest form that reads back to the identical double (full precision, no noise digits).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace mpmcut {

class CsvWriter {
 public:
  enum class Mode {
    Create,  // truncate and write the header
    Append,  // keep existing rows (restarts); the existing header must equal `columns`
  };

  // Opens `file`. In Append mode a missing or empty file gets the header; an existing header
  // that differs from `columns` throws std::runtime_error showing both; an incomplete last line
  // (a row cut off by a crash) is removed. Throws with path and system error when the file
  // cannot be opened. Column names must not contain commas, quotes or line breaks.
  CsvWriter(const std::filesystem::path& file, std::vector<std::string> columns,
            Mode mode = Mode::Create, bool flush_each_row = true);

  // Appends one row; values.size() must equal the number of columns.
  void row(std::span<const double> values);
  void row(std::initializer_list<double> values) { row(std::span<const double>(values)); }
  // Pushes buffered rows to the operating system; throws on a write error (e.g. disk full).
  void flush();

  const std::vector<std::string>& columns() const { return columns_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::filesystem::path file_;
  std::vector<std::string> columns_;
  bool flush_each_row_;
  std::unique_ptr<std::FILE, Closer> stream_;
};

}  // namespace mpmcut

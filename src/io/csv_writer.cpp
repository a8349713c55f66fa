#include "io/csv_writer.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

namespace mpmcut {

namespace {
std::string header_line(const std::vector<std::string>& columns) {
  return fmt::format("{}", fmt::join(columns, ","));
}

// Reads the first line of `file` and cuts a trailing partial line (no final '\n') off it.
std::string first_line_and_drop_partial_tail(const std::filesystem::path& file) {
  std::string header;
  {
    std::ifstream in(file, std::ios::binary);
    std::getline(in, header);
    if (!header.empty() && header.back() == '\r') header.pop_back();
    in.clear();
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    // Find the last '\n'; everything after it is a row that was being written when the run died.
    std::streamoff keep = 0;
    for (std::streamoff k = size - 1; k >= 0; --k) {
      in.seekg(k);
      if (in.get() == '\n') {
        keep = k + 1;
        break;
      }
    }
    if (keep == size) return header;
    if (keep == 0) header.clear();  // not even the header line is complete
    in.close();
    std::filesystem::resize_file(file, static_cast<std::uintmax_t>(keep));
  }
  return header;
}
}  // namespace

CsvWriter::CsvWriter(const std::filesystem::path& file, std::vector<std::string> columns,
                     Mode mode, bool flush_each_row)
    : file_(file), columns_(std::move(columns)), flush_each_row_(flush_each_row) {
  for (const std::string& c : columns_) {
    if (c.empty() || c.find_first_of(",\"\r\n") != std::string::npos) {
      throw std::invalid_argument(fmt::format("CSV column name '{}' is empty or contains a comma, "
                                              "quote or line break", c));
    }
  }
  const std::string header = header_line(columns_);
  bool write_header = true;
  if (mode == Mode::Append && std::filesystem::exists(file_) &&
      std::filesystem::file_size(file_) > 0) {
    const std::string existing = first_line_and_drop_partial_tail(file_);
    if (!existing.empty()) {
      if (existing != header) {
        throw std::runtime_error(fmt::format(
            "cannot append to '{}': its columns differ.\n  in the file: {}\n  expected:    {}",
            file_.string(), existing, header));
      }
      write_header = false;
    }
  }
  stream_.reset(std::fopen(file_.c_str(), mode == Mode::Append ? "ab" : "wb"));
  if (!stream_) {
    throw std::runtime_error(fmt::format("cannot open '{}' for writing: {}", file_.string(),
                                         std::strerror(errno)));
  }
  if (write_header) {
    fmt::print(stream_.get(), "{}\n", header);
    flush();
  }
}

void CsvWriter::row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(fmt::format("'{}': row has {} values for {} columns",
                                            file_.string(), values.size(), columns_.size()));
  }
  fmt::memory_buffer line;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k > 0) line.push_back(',');
    fmt::format_to(std::back_inserter(line), "{}", values[k]);  // shortest exact form
  }
  line.push_back('\n');
  if (std::fwrite(line.data(), 1, line.size(), stream_.get()) != line.size()) {
    throw std::runtime_error(
        fmt::format("cannot write to '{}': {}", file_.string(), std::strerror(errno)));
  }
  if (flush_each_row_) flush();
}

void CsvWriter::flush() {
  if (std::fflush(stream_.get()) != 0) {
    throw std::runtime_error(
        fmt::format("cannot write to '{}': {}", file_.string(), std::strerror(errno)));
  }
}

}  // namespace mpmcut

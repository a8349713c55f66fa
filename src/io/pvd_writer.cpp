#include "io/pvd_writer.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <fmt/core.h>

#include "io/atomic_file.hpp"
#include "io/whole_file.hpp"

namespace mpmcut {

namespace {
std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string xml_unescape(std::string s) {
  const std::pair<const char*, const char*> table[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}};  // &amp; last
  for (const auto& [from, to] : table) {
    for (std::size_t k = s.find(from); k != std::string::npos; k = s.find(from, k + 1)) {
      s.replace(k, std::string(from).size(), to);
    }
  }
  return s;
}
}  // namespace

void PvdSeries::drop_after(double time_s) {
  std::erase_if(entries_, [time_s](const Entry& e) { return e.time_s > time_s; });
}

void PvdSeries::write(const std::filesystem::path& index_file) const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Entry& e : entries_) {
    // Shortest representation that reads back to the same double.
    xml += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                       e.time_s, xml_escape(e.file));
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(index_file, [&](std::ostream& out) { out << xml; });
}

PvdSeries PvdSeries::read(const std::filesystem::path& index_file) {
  const std::optional<std::string> text = read_whole_file(index_file);
  if (!text) throw std::runtime_error(fmt::format("cannot read '{}'", index_file.string()));
  const std::string& s = *text;
  // Our own format: one <DataSet .../> per line with timestep before file.
  static const std::regex dataset(R"re(<DataSet\s[^>]*timestep="([^"]*)"[^>]*file="([^"]*)")re");
  PvdSeries series;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), dataset); it != std::sregex_iterator();
       ++it) {
    series.add(std::stod((*it)[1].str()), xml_unescape((*it)[2].str()));
  }
  return series;
}

}  // namespace mpmcut

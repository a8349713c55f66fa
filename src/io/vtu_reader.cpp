#include "io/vtu_reader.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <fmt/core.h>

#include "io/vtu_field_layout.hpp"
#include "io/whole_file.hpp"

namespace mpmcut {

static_assert(std::endian::native == std::endian::little,
              "the VTU reader maps LittleEndian bytes directly; add byte swapping for this host");

namespace {

// One <DataArray .../> declaration of the XML header.
struct ArrayDecl {
  std::string type;
  int components = 1;
  std::size_t offset = 0;
};

class Reader {
 public:
  explicit Reader(const std::filesystem::path& file) : file_(file) {
    std::optional<std::string> bytes = read_whole_file(file);
    if (!bytes) fail("cannot open the file");
    bytes_ = std::move(*bytes);
    parse_header();
  }

  std::size_t points() const { return n_; }

  // The payload of array `name`, checked against the expected type and component count.
  template <class T>
  std::vector<T> array(const std::string& name, const char* type, int components,
                       std::size_t tuples) const {
    const auto it = arrays_.find(name);
    if (it == arrays_.end()) fail(fmt::format("array '{}' is missing", name));
    const ArrayDecl& a = it->second;
    if (a.type != type || a.components != components)
      fail(fmt::format("array '{}' is {} with {} components, expected {} with {}", name, a.type,
                       a.components, type, components));
    const std::size_t want = tuples * components * sizeof(T);
    const std::size_t at = data_start_ + a.offset;
    if (at + sizeof(std::uint64_t) > data_end_)
      fail(fmt::format("array '{}' starts past the end of the appended data (truncated file?)", name));
    std::uint64_t size = 0;
    std::memcpy(&size, bytes_.data() + at, sizeof size);
    if (size != want)
      fail(fmt::format("array '{}' holds {} bytes, expected {} ({} tuples x {} x {} bytes)", name,
                       size, want, tuples, components, sizeof(T)));
    if (at + sizeof size + want > data_end_)
      fail(fmt::format("array '{}' runs past the end of the appended data (truncated file?)", name));
    std::vector<T> out(tuples * components);
    if (want > 0) std::memcpy(out.data(), bytes_.data() + at + sizeof size, want);
    return out;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(fmt::format("'{}' is not a readable mpmcut particle snapshot: {}",
                                         file_.string(), what));
  }

  // Whether the file has an array of this name.
  bool has(const std::string& name) const { return arrays_.count(name) > 0; }

 private:
  // The value of attribute `key` in the tag text `tag`, or "" when absent.
  static std::string attribute(std::string_view tag, std::string_view key) {
    std::string pattern = " ";  // appended, not `" " + ...`: GCC 12 warns falsely (-Wrestrict) on that
    pattern.append(key).append("=\"");
    const std::size_t at = tag.find(pattern);
    if (at == std::string_view::npos) return {};
    const std::size_t begin = at + pattern.size();
    const std::size_t end = tag.find('"', begin);
    if (end == std::string_view::npos) return {};
    return std::string(tag.substr(begin, end - begin));
  }

  static bool parse_size(const std::string& text, std::size_t& value) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
    try {
      value = std::stoull(text);
    } catch (...) {
      return false;
    }
    return true;
  }

  void parse_header() {
    constexpr std::string_view appended = "<AppendedData encoding=\"raw\">";
    const std::size_t data_tag = bytes_.find(appended);
    const std::string_view head = std::string_view(bytes_).substr(0, data_tag);
    if (bytes_.rfind("<?xml", 0) != 0 || head.find("<VTKFile") == std::string_view::npos)
      fail("it does not start with a VTK XML header");
    const std::size_t vtk_at = head.find("<VTKFile");
    const std::string_view vtk_tag = head.substr(vtk_at, head.find('>', vtk_at) - vtk_at);
    if (attribute(vtk_tag, "type") != "UnstructuredGrid")
      fail(fmt::format("VTKFile type is '{}', expected UnstructuredGrid", attribute(vtk_tag, "type")));
    if (attribute(vtk_tag, "byte_order") != "LittleEndian")
      fail("byte_order is not LittleEndian");
    if (attribute(vtk_tag, "header_type") != "UInt64")
      fail(fmt::format("header_type is '{}', expected UInt64", attribute(vtk_tag, "header_type")));
    if (head.find("compressor=") != std::string_view::npos) fail("compressed files are not supported");
    if (data_tag == std::string::npos) fail("no raw <AppendedData> block");

    const std::size_t piece_at = head.find("<Piece");
    if (piece_at == std::string_view::npos) fail("no <Piece>");
    const std::string_view piece = head.substr(piece_at, head.find('>', piece_at) - piece_at);
    if (!parse_size(attribute(piece, "NumberOfPoints"), n_)) fail("no valid NumberOfPoints");
    if (head.find("<Piece", piece_at + 1) != std::string_view::npos) fail("more than one <Piece>");

    for (std::size_t at = head.find("<DataArray"); at != std::string_view::npos;
         at = head.find("<DataArray", at + 1)) {
      const std::string_view tag = head.substr(at, head.find('>', at) - at);
      ArrayDecl a;
      const std::string name = attribute(tag, "Name");
      a.type = attribute(tag, "type");
      if (attribute(tag, "format") != "appended")
        fail(fmt::format("array '{}' is not in the appended block", name));
      std::size_t components = 1;
      const std::string c = attribute(tag, "NumberOfComponents");
      if (!c.empty() && (!parse_size(c, components) || components == 0 || components > 9))
        fail(fmt::format("array '{}' has NumberOfComponents=\"{}\"", name, c));
      a.components = static_cast<int>(components);
      if (!parse_size(attribute(tag, "offset"), a.offset))
        fail(fmt::format("array '{}' has no valid offset", name));
      arrays_[name] = a;
    }

    // Raw data start after the '_' marker; the writer closes with "\n  </AppendedData>\n</VTKFile>\n".
    const std::size_t marker = bytes_.find('_', data_tag + appended.size());
    if (marker == std::string::npos) fail("no '_' marker before the appended data");
    data_start_ = marker + 1;
    constexpr std::string_view trailer = "</AppendedData>";
    const std::size_t close = bytes_.rfind(trailer);
    if (close == std::string::npos || close < data_start_ ||
        bytes_.find("</VTKFile>", close) == std::string::npos)
      fail("the file ends before </AppendedData></VTKFile> (truncated?)");
    data_end_ = close;
  }

  std::filesystem::path file_;
  std::string bytes_;
  std::size_t n_ = 0;
  std::map<std::string, ArrayDecl> arrays_;
  std::size_t data_start_ = 0, data_end_ = 0;
};

// Reads field f's array into p (already sized); a kVtuOptional field that is absent keeps its
// initial value (a snapshot written before the field existed).
template <class T>
void read_field(const Reader& r, const ParticleField<T>& f, Particles& p) {
  const std::string name = vtu_array_name(f.info);
  if (!r.has(name) && f.info.has(kVtuOptional)) return;
  std::vector<T>& a = p.*f.array;
  const std::size_t n = r.points();
  if constexpr (std::is_same_v<T, std::int32_t>) {
    a = r.array<std::int32_t>(name, "Int32", 1, n);
  } else {
    constexpr int c = vtu_components(field_kind_of<T>());
    const std::vector<double> raw = r.array<double>(name, "Float64", c, n);
    for (std::size_t i = 0; i < n; ++i) from_vtk(&raw[i * c], a[i]);
  }
}

}  // namespace

VtuSnapshot read_particles_vtu(const std::filesystem::path& file) {
  const Reader r(file);
  const std::size_t n = r.points();
  VtuSnapshot snap;
  const std::vector<double> time = r.array<double>("TimeValue", "Float64", 1, 1);
  snap.time_s = time[0];

  // Every field flagged kVtuRead from its array; the others keep their initial value here.
  Particles& p = snap.particles;
  p.resize(n);
  for_each_particle_field([&](const auto& f) {
    if (f.info.has(kVtuRead)) read_field(r, f, p);
  });
  // Not in the file but rebuilt from J = V/V0 (= det F): F = sqrt(J) I, V0 = V / J.
  const std::vector<double> jacobian = r.array<double>("deformation_jacobian_J", "Float64", 1, n);
  for (std::size_t i = 0; i < n; ++i) {
    const double J = jacobian[i];
    if (!(J > 0.0))
      r.fail(fmt::format("particle {} has deformation_jacobian_J = {} (must be > 0)", i, J));
    p.deformation_gradient[i] = std::sqrt(J) * Mat2::Identity();
    p.initial_volume[i] = p.volume[i] / J;
  }
  return snap;
}

}  // namespace mpmcut

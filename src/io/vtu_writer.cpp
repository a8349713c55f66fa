#include "io/vtu_writer.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include <fmt/core.h>

#include "io/atomic_file.hpp"
#include "io/vtu_field_layout.hpp"

namespace mpmcut {

static_assert(std::endian::native == std::endian::little,
              "the VTU writer dumps memory as LittleEndian; add byte swapping for this host");

namespace {

// Point data computed from the fields for the reader's convenience; not stored per particle,
// not read back.
struct DerivedField {
  VtuFieldInfo info;
  double (*value)(const Particles& p, std::size_t i);
};

const std::vector<DerivedField>& derived_fields() {
  static const std::vector<DerivedField> table = {
      {{"von_mises_stress_Pa", 1, false, "von Mises equivalent of stress_Pa"},
       [](const Particles& p, std::size_t i) { return p.stress[i].von_mises(); }},
      {{"pressure_Pa", 1, false, "-trace(stress)/3, positive in compression"},
       [](const Particles& p, std::size_t i) { return -p.stress[i].mean(); }},
      {{"density_kg_per_m3", 1, false, "mass / volume"},
       [](const Particles& p, std::size_t i) { return p.mass[i] / p.volume[i]; }},
      {{"deformation_jacobian_J", 1, false, "J = det F, current over initial volume"},
       [](const Particles& p, std::size_t i) {
         return p.volume[i] / p.initial_volume[i];  // = det F (F_zz = 1), without its cancellation (advance_deformation)
       }},
  };
  return table;
}

// One DataArray in the appended block: declared in the XML at `offset`, its bytes produced
// on demand so that only one array is in memory at a time.
struct Block {
  std::string name;
  const char* type;  // VTK type name
  int components;
  std::size_t bytes;
  std::function<void(std::ostream&)> write_payload;
};

template <class T>
void write_raw(std::ostream& out, const std::vector<T>& v) {
  out.write(reinterpret_cast<const char*>(v.data()),
            static_cast<std::streamsize>(v.size() * sizeof(T)));
}

Block float64_block(std::string name, int components, std::size_t n,
                    std::function<void(std::vector<double>&)> fill) {
  const std::size_t bytes = n * components * sizeof(double);
  return {std::move(name), "Float64", components, bytes,
          [n, components, fill = std::move(fill)](std::ostream& out) {
            std::vector<double> buf(n * components);
            fill(buf);
            write_raw(out, buf);
          }};
}

Block int32_block(std::string name, int components, std::size_t n,
                  std::function<void(std::vector<std::int32_t>&)> fill) {
  const std::size_t bytes = n * components * sizeof(std::int32_t);
  return {std::move(name), "Int32", components, bytes,
          [n, components, fill = std::move(fill)](std::ostream& out) {
            std::vector<std::int32_t> buf(n * components);
            fill(buf);
            write_raw(out, buf);
          }};
}

// One registered field as point data (or as the Points), in VTK's components.
template <class T>
Block field_block(const Particles& p, const ParticleField<T>& f) {
  const std::vector<T>& a = p.*f.array;
  const std::size_t n = a.size();
  if constexpr (std::is_same_v<T, std::int32_t>) {
    return int32_block(vtu_array_name(f.info), 1, n,
                       [&a](std::vector<std::int32_t>& buf) { std::copy(a.begin(), a.end(), buf.begin()); });
  } else {
    constexpr int c = vtu_components(field_kind_of<T>());
    return float64_block(vtu_array_name(f.info), c, n, [&a, n](std::vector<double>& buf) {
      for (std::size_t i = 0; i < n; ++i) to_vtk(a[i], &buf[i * c]);
    });
  }
}

Block derived_block(const Particles& p, const DerivedField& f) {
  const std::size_t n = p.size();
  return float64_block(f.info.name, 1, n, [&p, &f, n](std::vector<double>& buf) {
    for (std::size_t i = 0; i < n; ++i) buf[i] = f.value(p, i);
  });
}

// Declares `blocks` in XML with consecutive offsets starting at `offset`; advances `offset`
// past each block's UInt64 size header and payload.
std::string declare(const std::vector<Block>& blocks, std::size_t& offset, const char* indent,
                    bool field_data) {
  std::string xml;
  for (const Block& b : blocks) {
    // meshio finds arrays by the exact text of `offset`, so it must be a bare integer.
    if (field_data) {
      xml += fmt::format(
          "{}<DataArray type=\"{}\" Name=\"{}\" NumberOfTuples=\"{}\" format=\"appended\" "
          "offset=\"{}\"/>\n",
          indent, b.type, b.name, b.bytes / 8, offset);
    } else {
      // Scalars leave NumberOfComponents at its default of 1, so readers give them shape (n,).
      const std::string components =
          b.components == 1 ? "" : fmt::format(" NumberOfComponents=\"{}\"", b.components);
      xml += fmt::format(
          "{}<DataArray type=\"{}\" Name=\"{}\"{} format=\"appended\" offset=\"{}\"/>\n",
          indent, b.type, b.name, components, offset);
    }
    offset += sizeof(std::uint64_t) + b.bytes;
  }
  return xml;
}

}  // namespace

const std::vector<VtuFieldInfo>& vtu_point_fields() {
  static const std::vector<VtuFieldInfo> infos = [] {
    std::vector<VtuFieldInfo> v;
    for_each_particle_field([&](const auto& f) {
      if (!vtu_point_data(f.info)) return;
      v.push_back({vtu_array_name(f.info), vtu_components(f.info.kind), f.info.kind == FieldKind::integer_id,
                   std::string(f.info.meaning)});
    });
    for (const DerivedField& f : derived_fields()) v.push_back(f.info);
    return v;
  }();
  return infos;
}

void write_particles_vtu(const Particles& p, const std::filesystem::path& file, double time_s) {
  const std::size_t n = p.size();
  if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() - 1)) {
    throw std::runtime_error(
        fmt::format("write_particles_vtu: {} particles exceed the Int32 cell indices", n));
  }

  auto constant = [](double value) {
    return [value](std::vector<double>& b) { b[0] = value; };
  };
  const std::vector<Block> field_data = {
      float64_block("TimeValue", 1, 1, constant(time_s)),  // ParaView's name for the time, s
      float64_block("time_s", 1, 1, constant(time_s)),
  };
  const std::vector<Block> points = [&p] {
    std::vector<Block> blocks;
    for_each_particle_field([&](const auto& f) {
      if (f.info.name == "position") blocks.push_back(field_block(p, f));
    });
    return blocks;
  }();
  Block types{"types", "UInt8", 1, n, [n](std::ostream& out) {
                constexpr std::uint8_t vtk_vertex = 1;
                const std::vector<std::uint8_t> buf(n, vtk_vertex);
                write_raw(out, buf);
              }};
  const std::vector<Block> cells = {
      int32_block("connectivity", 1, n,
                  [n](std::vector<std::int32_t>& b) {
                    for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::int32_t>(i);
                  }),
      int32_block("offsets", 1, n,
                  [n](std::vector<std::int32_t>& b) {
                    for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::int32_t>(i + 1);
                  }),
      std::move(types)};
  const std::vector<Block> point_data = [&p] {
    std::vector<Block> blocks;
    for_each_particle_field([&](const auto& f) {
      if (vtu_point_data(f.info)) blocks.push_back(field_block(p, f));
    });
    for (const DerivedField& f : derived_fields()) blocks.push_back(derived_block(p, f));
    return blocks;
  }();

  std::size_t offset = 0;
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n"
      "    <FieldData>\n";
  xml += declare(field_data, offset, "      ", true);
  xml += "    </FieldData>\n";
  xml += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, n);
  xml += "      <Points>\n" + declare(points, offset, "        ", false) + "      </Points>\n";
  xml += "      <Cells>\n" + declare(cells, offset, "        ", false) + "      </Cells>\n";
  xml += "      <PointData>\n" + declare(point_data, offset, "        ", false) +
         "      </PointData>\n";
  xml += "    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";

  write_file_atomically(file, [&](std::ostream& out) {
    out << xml;
    for (const std::vector<Block>* group : {&field_data, &points, &cells, &point_data}) {
      for (const Block& b : *group) {
        const std::uint64_t size = b.bytes;
        out.write(reinterpret_cast<const char*>(&size), sizeof size);
        b.write_payload(out);
      }
    }
    // meshio drops everything after the last newline before </AppendedData>: keep this one.
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

}  // namespace mpmcut

#include "io/vtu_writer.hpp"

#include <bit>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>

#include <fmt/core.h>

#include "io/atomic_file.hpp"

namespace mpmcut {

static_assert(std::endian::native == std::endian::little,
              "the VTU writer dumps memory as LittleEndian; add byte swapping for this host");

namespace {

// A point-data field: its description and how to get one particle's components.
// Integer fields return exact small integers through the double and are stored as Int32.
struct Field {
  VtuFieldInfo info;
  void (*value)(const Particles& p, std::size_t i, double* out);
};

void symmetric_tensor(const PlaneStrainTensor& t, double* out) {
  // VTK order xx yy zz xy yz xz; yz = xz = 0 in plane strain.
  out[0] = t.xx; out[1] = t.yy; out[2] = t.zz; out[3] = t.xy; out[4] = 0.0; out[5] = 0.0;
}

const std::vector<Field>& fields() {
  static const std::vector<Field> table = {
      {{"velocity_m_per_s", 3, false, "particle velocity (z = 0)"},
       [](const Particles& p, std::size_t i, double* o) {
         o[0] = p.velocity[i].x(); o[1] = p.velocity[i].y(); o[2] = 0.0;
       }},
      {{"stress_Pa", 6, false, "Cauchy stress with damage applied (xx yy zz xy yz xz)"},
       [](const Particles& p, std::size_t i, double* o) { symmetric_tensor(p.stress[i], o); }},
      {{"von_mises_stress_Pa", 1, false, "von Mises equivalent of stress_Pa"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.stress[i].von_mises(); }},
      {{"pressure_Pa", 1, false, "-trace(stress)/3, positive in compression"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = -p.stress[i].mean(); }},
      {{"effective_stress_Pa", 6, false, "undamaged stress of the return mapping"},
       [](const Particles& p, std::size_t i, double* o) {
         symmetric_tensor(p.effective_stress[i], o);
       }},
      {{"mass_kg_per_m", 1, false, "particle mass per m of thickness"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.mass[i]; }},
      {{"volume_m3_per_m", 1, false, "current particle volume per m of thickness (an area)"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.volume[i]; }},
      {{"density_kg_per_m3", 1, false, "mass / volume"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.mass[i] / p.volume[i]; }},
      {{"body_id", 1, true, "index of the body in the scene"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.body[i]; }},
      {{"material_id", 1, true, "index of the material"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.material[i]; }},
      {{"plastic_strain", 1, false, "equivalent plastic strain"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.plastic_strain[i]; }},
      {{"plastic_strain_rate_per_s", 1, false, "smoothed equivalent plastic strain rate"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.plastic_strain_rate[i]; }},
      {{"temperature_K", 1, false, "temperature"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.temperature[i]; }},
      {{"damage_initiation", 1, false, "Johnson-Cook initiation indicator omega (>= 1: initiated)"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.damage_initiation[i]; }},
      {{"damage", 1, false, "damage D in [0, 1]"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.damage[i]; }},
      {{"plastic_displacement_m", 1, false, "plastic displacement after damage initiation"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.plastic_displacement[i]; }},
      {{"fracture_energy_J_per_m2", 1, false, "G_f fixed at damage initiation (0 before)"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.fracture_energy[i]; }},
      {{"damage_dissipation_J_per_m", 1, false,
        "damage dissipation of the particle since the start (per m of thickness); / G_f = its crack length"},
       [](const Particles& p, std::size_t i, double* o) { o[0] = p.damage_dissipation[i]; }},
      {{"deformation_jacobian_J", 1, false, "J = det F, current over initial volume"},
       [](const Particles& p, std::size_t i, double* o) {
         o[0] = p.deformation_gradient[i].determinant();  // F_zz = 1 in plane strain
       }},
      {{"velocity_gradient_per_s", 9, false, "L = grad v, row-major, L_ij = dv_i/dx_j"},
       [](const Particles& p, std::size_t i, double* o) {
         const Mat2& L = p.velocity_gradient[i];
         o[0] = L(0, 0); o[1] = L(0, 1); o[2] = 0.0;
         o[3] = L(1, 0); o[4] = L(1, 1); o[5] = 0.0;
         o[6] = 0.0;     o[7] = 0.0;     o[8] = 0.0;
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

Block field_block(const Particles& p, const Field& f) {
  const std::size_t n = p.size();
  const int c = f.info.components;
  if (!f.info.integer) {
    return float64_block(f.info.name, c, n, [&p, &f, c, n](std::vector<double>& buf) {
      for (std::size_t i = 0; i < n; ++i) f.value(p, i, &buf[i * c]);
    });
  }
  return int32_block(f.info.name, c, n, [&p, &f, c, n](std::vector<std::int32_t>& buf) {
    double v[9];
    for (std::size_t i = 0; i < n; ++i) {
      f.value(p, i, v);
      for (int k = 0; k < c; ++k) buf[i * c + k] = static_cast<std::int32_t>(v[k]);
    }
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
    for (const Field& f : fields()) v.push_back(f.info);
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
  const std::vector<Block> points = {
      float64_block("Points", 3, n, [&p, n](std::vector<double>& b) {
        for (std::size_t i = 0; i < n; ++i) {
          b[3 * i] = p.position[i].x(); b[3 * i + 1] = p.position[i].y(); b[3 * i + 2] = 0.0;
        }
      })};
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
    for (const Field& f : fields()) blocks.push_back(field_block(p, f));
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

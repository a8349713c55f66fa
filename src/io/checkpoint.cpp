#include "io/checkpoint.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "io/whole_file.hpp"

namespace mpmcut {

static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian; add byte swapping");

namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'M', 'P', 'M', 'C', 'U', 'T', 'C', 'K'};
constexpr std::uint32_t kHeaderBytes = 32;

// --- Every field of the state, listed once --------------------------------------------------
// The particle arrays come from the field registry (core/particle_fields.hpp): every field flagged
// kCheckpoint is a section particles.<name> of raw values. A field added to EnergyTotals or
// RigidBodyState without being added here would be silently lost on restart; these checks turn
// that into a compile error.
struct EnergyLayout {
  double a, b, c, d, e, f, g, h, i, j, k, l;
};
static_assert(sizeof(EnergyTotals) == sizeof(EnergyLayout),
              "EnergyTotals gained or lost a field: update energy_fields() in io/checkpoint.cpp");
struct RigidLayout {
  std::string name;
  Vec2 a, b, c, d, e;
  double f;
  std::vector<double> g, h;  // the conducting bodies' fields: section rigid_body_temperatures
};
static_assert(sizeof(RigidBodyState) == sizeof(RigidLayout),
              "RigidBodyState gained or lost a field: update the rigid-body section in io/checkpoint.cpp");
struct RestartLayout {
  double a;
  long b;
  double c;
  std::vector<RigidBodyState> d;
  EnergyTotals e;
  long f;
  double g;
  ConductionSubcycle h;
};
static_assert(sizeof(RestartState) == sizeof(RestartLayout),
              "RestartState gained or lost a field: update write_checkpoint_file() and decode_checkpoint() in "
              "io/checkpoint.cpp and bump kCheckpointFormatVersion");
struct ConductionLayout {
  double a;
  int b;
};
static_assert(sizeof(ConductionSubcycle) == sizeof(ConductionLayout),
              "ConductionSubcycle gained or lost a field: update the conduction section in io/checkpoint.cpp");
static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(Mat2) == 4 * sizeof(double) &&
              sizeof(PlaneStrainTensor) == 4 * sizeof(double));

template <class E>
auto energy_fields(E& e) {
  return std::array{&e.kinetic, &e.elastic, &e.plastic_work, &e.heat, &e.damage_dissipation, &e.friction,
                    &e.viscous, &e.external_work, &e.transfer_dissipation, &e.contact_safeguard,
                    &e.removed_energy, &e.initial};
}

// --- Little-endian byte building and reading ------------------------------------------------

class Bytes {
 public:
  void u32(std::uint32_t v) { raw(&v, sizeof v); }
  void u64(std::uint64_t v) { raw(&v, sizeof v); }
  void i64(std::int64_t v) { raw(&v, sizeof v); }
  void f64(double v) { raw(&v, sizeof v); }
  void vec(const Vec2& v) { f64(v.x()), f64(v.y()); }
  void str(std::string_view s) {
    u64(s.size());
    raw(s.data(), s.size());
  }
  void raw(const void* p, std::size_t n) { data_.append(static_cast<const char*>(p), n); }
  const std::string& data() const { return data_; }

 private:
  std::string data_;
};

class Reader {
 public:
  Reader(std::string_view data, std::string what) : data_(data), what_(std::move(what)) {}
  std::uint32_t u32() { return get<std::uint32_t>(); }
  std::uint64_t u64() { return get<std::uint64_t>(); }
  std::int64_t i64() { return get<std::int64_t>(); }
  double f64() { return get<double>(); }
  Vec2 vec() {
    const double x = f64();
    return {x, f64()};
  }
  std::string str() {
    const std::uint64_t n = u64();
    return std::string(take(n));
  }
  std::string_view take(std::uint64_t n) {
    if (n > data_.size() - pos_) fail(fmt::format("needs {} more bytes at offset {}, has {}", n, pos_, data_.size() - pos_));
    const std::string_view s = data_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  bool done() const { return pos_ == data_.size(); }
  std::size_t pos() const { return pos_; }
  [[noreturn]] void fail(const std::string& why) const { throw CheckpointError(what_ + ": " + why); }

 private:
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, take(sizeof v).data(), sizeof v);
    return v;
  }
  std::string_view data_;
  std::size_t pos_ = 0;
  std::string what_;
};

std::uint32_t crc32_of(std::uint32_t crc, const void* p, std::size_t n) {
  return static_cast<std::uint32_t>(crc32_z(crc, static_cast<const Bytef*>(p), n));
}

std::string system_error(const std::string& what, const fs::path& file) {
  return fmt::format("cannot {} '{}': {}", what, file.string(), std::strerror(errno));
}

// A file written with plain POSIX calls, so that it can be fsynced and every error is seen
// (EFBIG under a file-size limit, ENOSPC on a full disk, EIO).
class SyncedFile {
 public:
  explicit SyncedFile(const fs::path& file) : file_(file) {
    fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error(system_error("create", file));
  }
  ~SyncedFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  SyncedFile(const SyncedFile&) = delete;
  SyncedFile& operator=(const SyncedFile&) = delete;

  void write(const void* data, std::size_t n) {
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
      const ssize_t w = ::write(fd_, p, std::min<std::size_t>(n, 1u << 30));
      if (w < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error(system_error("write", file_));
      }
      p += w;
      n -= static_cast<std::size_t>(w);
    }
  }
  void write_at(std::uint64_t offset, const void* data, std::size_t n) {
    if (::pwrite(fd_, data, n, static_cast<off_t>(offset)) != static_cast<ssize_t>(n))
      throw std::runtime_error(system_error("write", file_));
  }
  void sync_and_close() {
    if (::fsync(fd_) != 0) throw std::runtime_error(system_error("fsync", file_));
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw std::runtime_error(system_error("close", file_));
  }

 private:
  fs::path file_;
  int fd_ = -1;
};

// Makes a rename or create inside `dir` durable.
void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(system_error("open folder", dir));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  errno = err;
  if (rc != 0 && errno != EINVAL) throw std::runtime_error(system_error("fsync folder", dir));
}

// Streams the payload to a SyncedFile: sections, CRC and length as it goes.
class PayloadWriter {
 public:
  explicit PayloadWriter(SyncedFile& out) : out_(out) {}
  void section(std::string_view name, const void* data, std::size_t n) {
    Bytes head;
    head.u32(static_cast<std::uint32_t>(name.size()));
    head.raw(name.data(), name.size());
    head.u64(n);
    put(head.data().data(), head.data().size());
    put(data, n);
  }
  void section(std::string_view name, const Bytes& b) { section(name, b.data().data(), b.data().size()); }
  std::uint64_t size() const { return size_; }
  std::uint32_t crc() const { return crc_; }

 private:
  void put(const void* p, std::size_t n) {
    crc_ = crc32_of(crc_, p, n);
    size_ += n;
    out_.write(p, n);
  }
  SyncedFile& out_;
  std::uint64_t size_ = 0;
  std::uint32_t crc_ = crc32_of(0, nullptr, 0);
};

std::string header_bytes(std::uint64_t payload_size, std::uint32_t payload_crc) {
  Bytes h;
  h.raw(kMagic, sizeof kMagic);
  h.u32(kCheckpointFormatVersion);
  h.u32(kHeaderBytes);
  h.u64(payload_size);
  h.u32(payload_crc);
  h.u32(crc32_of(crc32_of(0, nullptr, 0), h.data().data(), h.data().size()));
  return h.data();
}

std::string particle_section_name(std::string_view field) { return "particles." + std::string(field); }

long step_of_checkpoint_name(const std::string& name) {
  constexpr std::string_view prefix = "checkpoint_", suffix = ".bin";
  if (name.size() <= prefix.size() + suffix.size() || !name.starts_with(prefix) || !name.ends_with(suffix)) return -1;
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  if (digits.empty() || digits.size() > 18 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) return -1;
  return std::stol(digits);
}

void write_small_file_synced(const fs::path& file, const std::string& text) {
  SyncedFile f(file);
  f.write(text.data(), text.size());
  f.sync_and_close();
}

}  // namespace

// ---------------------------------------------------------------------------------------------

void write_checkpoint_file(const fs::path& file, const Simulation& sim, std::uint64_t scene_hash,
                           const RunLoopState& loop) {
  SyncedFile out(file);
  const std::string placeholder(kHeaderBytes, '\0');
  out.write(placeholder.data(), placeholder.size());
  PayloadWriter w(out);

  Bytes meta;
  meta.u64(scene_hash);
  meta.str(loop.mpmcut_version);
  meta.str(loop.case_file);
  meta.i64(loop.threads);
  meta.f64(loop.wall_time_s);
  meta.i64(loop.checkpoint_kind);
  meta.f64(loop.checkpoint_value);
  w.section("meta", meta);

  const RestartState& state = sim.restart_state();
  Bytes clock;
  clock.f64(state.time);
  clock.i64(state.step);
  clock.f64(state.last_dt);
  w.section("clock", clock);

  const Particles& P = sim.particles();
  Bytes count;
  count.u64(P.size());
  w.section("particles", count);
  for_each_particle_field([&](const auto& f) {
    if (!f.info.has(kCheckpoint)) return;
    const auto& array = P.*f.array;
    w.section(particle_section_name(f.info.name), array.data(), array.size() * sizeof(array[0]));
  });

  Bytes rigid;
  rigid.u64(state.rigid_bodies.size());
  for (const RigidBodyState& r : state.rigid_bodies) {
    rigid.str(r.name);
    rigid.vec(r.velocity);
    rigid.vec(r.displacement);
    rigid.vec(r.force);
    rigid.vec(r.impulse);
    rigid.vec(r.step_impulse);
    rigid.f64(r.work);
  }
  w.section("rigid_bodies", rigid);
  // Conducting bodies' temperature fields (a section of its own: checkpoints from before it read without it).
  Bytes fields;
  fields.u64(state.rigid_bodies.size());
  for (const RigidBodyState& r : state.rigid_bodies) {
    for (const auto* v : {&r.temperature_field, &r.heat_input_average}) {
      fields.u64(v->size());
      for (const double x : *v) fields.f64(x);
    }
  }
  w.section("rigid_body_temperatures", fields);

  Bytes energy;
  for (const double* e : energy_fields(state.energy)) energy.f64(*e);
  energy.i64(state.removed_particles);
  energy.f64(state.removed_mass);
  w.section("energy", energy);

  Bytes conduction;
  conduction.f64(state.conduction.elapsed);
  conduction.i64(state.conduction.steps);
  w.section("conduction", conduction);

  Bytes run;
  run.f64(loop.next_snapshot_s);
  run.f64(loop.next_history_s);
  run.i64(loop.snapshot_count);
  run.f64(loop.last_snapshot_time_s);
  run.u64(loop.pvd.size());
  for (const auto& e : loop.pvd) {
    run.f64(e.time_s);
    run.str(e.file);
  }
  run.u64(loop.files.size());
  for (const auto& f : loop.files) {
    run.str(f.relative_path);
    run.u64(f.bytes);
  }
  run.u64(loop.observer_states.size());
  for (const auto& s : loop.observer_states) run.str(s);
  w.section("run_loop", run);

  const std::string header = header_bytes(w.size(), w.crc());
  out.write_at(0, header.data(), header.size());
  out.sync_and_close();
}

Checkpoint decode_checkpoint(std::string_view bytes, const std::string& name) {
  // Header: is it a checkpoint at all, is it complete, is it intact.
  if (bytes.size() < kHeaderBytes) {
    throw CheckpointError(fmt::format("checkpoint '{}' is truncated: {} bytes, shorter than the {}-byte header", name,
                                      bytes.size(), kHeaderBytes));
  }
  if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw CheckpointError(fmt::format("'{}' is not an mpmcut checkpoint (wrong magic bytes)", name));
  Reader h(bytes.substr(0, kHeaderBytes), fmt::format("checkpoint '{}' header", name));
  h.take(sizeof kMagic);
  const std::uint32_t version = h.u32();
  const std::uint32_t header_size = h.u32();
  const std::uint64_t payload_size = h.u64();
  const std::uint32_t payload_crc = h.u32();
  const std::uint32_t header_crc = h.u32();
  if (crc32_of(crc32_of(0, nullptr, 0), bytes.data(), kHeaderBytes - 4) != header_crc)
    throw CheckpointError(fmt::format("checkpoint '{}' is corrupt: header CRC mismatch", name));
  if (version != kCheckpointFormatVersion || header_size != kHeaderBytes) {
    throw CheckpointError(fmt::format("checkpoint '{}' has format version {}; this mpmcut reads version {}", name,
                                      version, kCheckpointFormatVersion));
  }
  const std::uint64_t expected = kHeaderBytes + payload_size;
  if (bytes.size() < expected)
    throw CheckpointError(fmt::format("checkpoint '{}' is truncated: {} of {} bytes", name, bytes.size(), expected));
  if (bytes.size() > expected)
    throw CheckpointError(
        fmt::format("checkpoint '{}' is corrupt: {} bytes, {} more than its header says", name, bytes.size(),
                    bytes.size() - expected));
  const std::string_view payload = bytes.substr(kHeaderBytes);
  if (crc32_of(crc32_of(0, nullptr, 0), payload.data(), payload.size()) != payload_crc)
    throw CheckpointError(fmt::format("checkpoint '{}' is corrupt: payload CRC mismatch (bit flip or overwritten data)",
                                      name));

  // Payload: named sections.
  std::map<std::string, std::string_view, std::less<>> sections;
  Reader all(payload, fmt::format("checkpoint '{}'", name));
  while (!all.done()) {
    const std::uint32_t n = all.u32();
    std::string key(all.take(n));
    sections[key] = all.take(all.u64());
  }
  auto section = [&](const std::string& key) {
    const auto it = sections.find(key);
    if (it == sections.end()) all.fail("has no section '" + key + "'");
    return Reader(it->second, fmt::format("checkpoint '{}', section '{}'", name, key));
  };
  auto finish = [](Reader& r) {
    if (!r.done()) r.fail(fmt::format("{} unexpected bytes at the end", r.pos()));
  };

  Checkpoint c;
  {
    Reader r = section("meta");
    c.scene_hash = r.u64();
    c.loop.mpmcut_version = r.str();
    c.loop.case_file = r.str();
    c.loop.threads = static_cast<int>(r.i64());
    c.loop.wall_time_s = r.f64();
    c.loop.checkpoint_kind = static_cast<int>(r.i64());
    c.loop.checkpoint_value = r.f64();
    finish(r);
  }
  {
    Reader r = section("clock");
    c.state.time = r.f64();
    c.state.step = r.i64();
    c.state.last_dt = r.f64();
    finish(r);
  }
  {
    Reader r = section("particles");
    const std::uint64_t n = r.u64();
    finish(r);
    // Every checkpointed field must be there with n values before n is trusted for allocating. A
    // file without a field comes from an mpmcut without it: refuse rather than guess.
    for_each_particle_field([&](const auto& f) {
      if (!f.info.has(kCheckpoint)) return;
      const std::string key = particle_section_name(f.info.name);
      const auto it = sections.find(key);
      if (it == sections.end())
        all.fail(fmt::format("has no particle field '{}' (written by an mpmcut without that field)", f.info.name));
      const std::size_t value_bytes = sizeof((c.particles.*f.array)[0]);
      if (it->second.size() % value_bytes != 0 || it->second.size() / value_bytes != n)
        all.fail(fmt::format("section '{}' holds {} bytes, not {} particles of {} bytes", key, it->second.size(), n,
                             value_bytes));
    });
    c.particles.resize(n);  // fields without kCheckpoint keep their initial value
    for_each_particle_field([&](const auto& f) {
      if (!f.info.has(kCheckpoint)) return;
      auto& array = c.particles.*f.array;
      const std::string_view data = sections.find(particle_section_name(f.info.name))->second;
      std::memcpy(static_cast<void*>(array.data()), data.data(), data.size());
    });
  }
  {
    Reader r = section("rigid_bodies");
    const std::uint64_t n = r.u64();
    if (n > payload.size()) r.fail("implausible rigid body count");
    for (std::uint64_t k = 0; k < n; ++k) {
      RigidBodyState s;
      s.name = r.str();
      s.velocity = r.vec();
      s.displacement = r.vec();
      s.force = r.vec();
      s.impulse = r.vec();
      s.step_impulse = r.vec();
      s.work = r.f64();
      c.state.rigid_bodies.push_back(s);
    }
    finish(r);
  }
  if (sections.count("rigid_body_temperatures")) {
    Reader r = section("rigid_body_temperatures");
    if (r.u64() != c.state.rigid_bodies.size()) r.fail("holds fields for another number of rigid bodies");
    for (RigidBodyState& s : c.state.rigid_bodies) {
      for (auto* v : {&s.temperature_field, &s.heat_input_average}) {
        const std::uint64_t cells = r.u64();
        if (cells > payload.size() / sizeof(double)) r.fail("implausible cell count");
        v->resize(cells);
        for (double& x : *v) x = r.f64();
      }
    }
    finish(r);
  }
  {
    Reader r = section("energy");
    for (double* e : energy_fields(c.state.energy)) *e = r.f64();
    c.state.removed_particles = r.i64();
    c.state.removed_mass = r.f64();
    finish(r);
  }
  {
    Reader r = section("conduction");
    c.state.conduction.elapsed = r.f64();
    c.state.conduction.steps = static_cast<int>(r.i64());
    finish(r);
  }
  {
    Reader r = section("run_loop");
    c.loop.next_snapshot_s = r.f64();
    c.loop.next_history_s = r.f64();
    c.loop.snapshot_count = static_cast<int>(r.i64());
    c.loop.last_snapshot_time_s = r.f64();
    const std::uint64_t entries = r.u64();
    if (entries > payload.size()) r.fail("implausible PVD entry count");
    for (std::uint64_t k = 0; k < entries; ++k) {
      const double t = r.f64();
      c.loop.pvd.push_back({t, r.str()});
    }
    const std::uint64_t files = r.u64();
    if (files > payload.size()) r.fail("implausible file count");
    for (std::uint64_t k = 0; k < files; ++k) {
      FileLength f;
      f.relative_path = r.str();
      f.bytes = r.u64();
      c.loop.files.push_back(f);
    }
    const std::uint64_t observers = r.u64();
    if (observers > payload.size()) r.fail("implausible observer count");
    for (std::uint64_t k = 0; k < observers; ++k) c.loop.observer_states.push_back(r.str());
    finish(r);
  }
  return c;
}

Checkpoint read_checkpoint_file(const fs::path& file) {
  const std::optional<std::string> bytes = read_whole_file(file);
  if (!bytes) throw CheckpointError(system_error("read checkpoint", file));
  return decode_checkpoint(*bytes, file.string());
}

void Checkpoint::restore(Simulation& sim) && {
  const std::string where = fmt::format("checkpoint at step {}", state.step);
  const Scene& scene = sim.scene();
  const std::vector<RigidBodyState>& rigid_bodies = state.rigid_bodies;
  if (rigid_bodies.size() != sim.rigid_bodies().size())
    throw CheckpointError(fmt::format("{} has {} rigid bodies, the scene {}", where, rigid_bodies.size(),
                                      sim.rigid_bodies().size()));
  for (std::size_t r = 0; r < rigid_bodies.size(); ++r) {
    if (rigid_bodies[r].name != sim.rigid_bodies()[r].name)
      throw CheckpointError(fmt::format("{}: rigid body {} is '{}', the scene's is '{}'", where, r,
                                        rigid_bodies[r].name, sim.rigid_bodies()[r].name));
  }
  // A CRC-valid file from this program is consistent; these checks keep a hand-made one from
  // indexing out of bounds.
  const std::size_t n = particles.size();
  for_each_particle_field([&](const auto& f) {
    if ((particles.*f.array).size() != n)
      throw CheckpointError(fmt::format("{}: particle array '{}' has the wrong length", where, f.info.name));
  });
  for (std::size_t p = 0; p < n; ++p) {
    if (particles.body[p] < 0 || static_cast<std::size_t>(particles.body[p]) >= scene.bodies.size() ||
        particles.material[p] < 0 || static_cast<std::size_t>(particles.material[p]) >= scene.materials.size())
      throw CheckpointError(fmt::format("{}: particle {} has body {} / material {}, not in the scene", where, p,
                                        particles.body[p], particles.material[p]));
  }
  sim.particles() = std::move(particles);
  sim.restore(state);
}

// ---------------------------------------------------------------------------------------------

CheckpointStore::CheckpointStore(const fs::path& result_dir) : folder_(result_dir / "checkpoints") {}

std::vector<fs::path> CheckpointStore::list() const {
  std::vector<std::pair<long, fs::path>> found;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder_, ec)) {
    const long step = step_of_checkpoint_name(e.path().filename().string());
    if (step >= 0 && e.is_regular_file(ec)) found.emplace_back(step, e.path());
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<fs::path> files;
  for (auto& f : found) files.push_back(std::move(f.second));
  return files;
}

fs::path CheckpointStore::write(const Simulation& sim, std::uint64_t scene_hash, const RunLoopState& loop) {
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create '{}': {}", folder_.string(), ec.message()));
  const fs::path tmp = folder_ / "checkpoint.tmp";
  const fs::path file = folder_ / fmt::format("checkpoint_{}.bin", sim.step_count());
  try {
    write_checkpoint_file(tmp, sim, scene_hash, loop);
    fs::rename(tmp, file);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  sync_directory(folder_);
  // The pointer, replaced the same way.
  const fs::path pointer_tmp = folder_ / "latest.tmp";
  try {
    write_small_file_synced(pointer_tmp, file.filename().string() + "\n");
    fs::rename(pointer_tmp, folder_ / "latest");
  } catch (...) {
    fs::remove(pointer_tmp, ec);
    throw;
  }
  sync_directory(folder_);
  // Only now is the old one expendable; the one before this is kept as a fallback.
  for (const fs::path& old : list()) {
    if (old != file && old != previous_) fs::remove(old, ec);
  }
  previous_ = file;
  return file;
}

CheckpointStore::Loaded CheckpointStore::load_newest_valid() const {
  std::vector<fs::path> candidates;
  std::vector<std::string> rejected;
  const fs::path pointer = folder_ / "latest";
  if (std::ifstream in(pointer); in) {
    std::string name;
    std::getline(in, name);
    if (step_of_checkpoint_name(name) >= 0 && fs::exists(folder_ / name)) {
      candidates.push_back(folder_ / name);
    } else {
      rejected.push_back(fmt::format("'{}' names '{}', which does not exist", pointer.string(), name));
    }
  }
  for (const fs::path& f : list())
    if (candidates.empty() || f != candidates.front()) candidates.push_back(f);
  for (const fs::path& f : candidates) {
    try {
      Loaded loaded{read_checkpoint_file(f), f, rejected};
      return loaded;
    } catch (const CheckpointError& e) {
      rejected.push_back(e.what());
    }
  }
  std::string message = fmt::format("no usable checkpoint in '{}'", folder_.string());
  if (candidates.empty()) message += " (there are none: the run stopped before its first checkpoint)";
  for (const std::string& r : rejected) message += "\n  " + r;
  throw CheckpointError(message);
}

}  // namespace mpmcut

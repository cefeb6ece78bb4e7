#pragma once
// One particle's whole state as it travels between ranks (migration, ghosts, gathering), and the
// byte buffers messages are packed into.
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "core/errors.hpp"
#include "dem/particles.hpp"

namespace trapdem {

struct ParticleRecord {
  std::int64_t id;
  double radius, mass, inv_mass, inv_inertia;
  Vec3 position, velocity, angular_velocity, force, torque;
  Int3 image;
};
static_assert(std::is_trivially_copyable_v<ParticleRecord>);

inline ParticleRecord record_of(const Particles& p, std::size_t i) {
  return {p.id[i],       p.radius[i],           p.mass[i],  p.inv_mass[i], p.inv_inertia[i], p.position[i],
          p.velocity[i], p.angular_velocity[i], p.force[i], p.torque[i],   p.image[i]};
}

inline void append_record(Particles& p, const ParticleRecord& r) {
  p.id.push_back(r.id);
  p.radius.push_back(r.radius);
  p.mass.push_back(r.mass);
  p.inv_mass.push_back(r.inv_mass);
  p.inv_inertia.push_back(r.inv_inertia);
  p.position.push_back(r.position);
  p.velocity.push_back(r.velocity);
  p.angular_velocity.push_back(r.angular_velocity);
  p.force.push_back(r.force);
  p.torque.push_back(r.torque);
  p.image.push_back(r.image);
}

// A message: arrays of trivially copyable values, each preceded by its length.
class Packer {
 public:
  template <class T>
  void put(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::uint64_t n = values.size();
    append(&n, sizeof n);
    append(values.data(), n * sizeof(T));
  }
  std::vector<char>& bytes() { return bytes_; }

 private:
  void append(const void* data, std::size_t size) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + size);
    if (size > 0) std::memcpy(bytes_.data() + at, data, size);
  }
  std::vector<char> bytes_;
};

class Unpacker {
 public:
  explicit Unpacker(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <class T>
  std::vector<T> get() {
    std::uint64_t n = 0;
    if (bytes_.size() - at_ < sizeof n) throw FileError("a message or checkpointed state ends before its data");
    std::memcpy(&n, bytes_.data() + at_, sizeof n);
    at_ += sizeof n;
    if ((bytes_.size() - at_) / sizeof(T) < n) throw FileError("a message or checkpointed state ends before its data");
    std::vector<T> values(n);
    if (n > 0) std::memcpy(values.data(), bytes_.data() + at_, n * sizeof(T));
    at_ += n * sizeof(T);
    return values;
  }

 private:
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

}  // namespace trapdem

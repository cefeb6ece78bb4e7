#pragma once
// A thin RAII layer over the HDF5 C API: files, groups, 1-D, N x 3 and N x 4 datasets, scalar attributes.
// Only what trapdem's files need. Every failure throws FileError naming the file, the object path
// inside it and the HDF5 library's own reason; HDF5's automatic printing of its error stack to
// stderr is switched off (the message carries the reason instead).
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dem/particles.hpp"
#include "dem/rigid/quaternion.hpp"
#include "dem/vec3.hpp"
#include "core/errors.hpp"

namespace trapdem {

// Layers of 2-D float fields, value[(layer * rows + row) * columns + column].
struct FloatStack {
  std::size_t layers = 0, rows = 0, columns = 0;
  std::vector<float> value;
};

// Owns one HDF5 identifier and closes it with the matching H5*close.
class Hdf5Handle {
 public:
  Hdf5Handle() = default;
  explicit Hdf5Handle(hid_t id) : id_(id) {}
  Hdf5Handle(Hdf5Handle&& other) noexcept : id_(other.id_) { other.id_ = H5I_INVALID_HID; }
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  ~Hdf5Handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset();                       // closes (errors ignored: used on unwinding)
  hid_t release();                    // gives up ownership

 private:
  hid_t id_ = H5I_INVALID_HID;
};

// A group (the file's root group included): create and open children, write and read datasets
// and attributes. Dataset names are relative to the group.
class Hdf5Group {
 public:
  const std::string& file_name() const { return file_; }
  const std::string& path() const { return path_; }   // inside the file: "/", "/snapshots/000003"
  hid_t id() const { return handle_.get(); }

  bool has(std::string_view name) const;               // a child link (group or dataset) exists
  Hdf5Group create_group(std::string_view name) const;
  Hdf5Group group(std::string_view name) const;        // FileError if absent
  std::vector<std::string> children() const;           // child names in name order
  void remove(std::string_view name) const;             // unlinks a child (its space is not reclaimed)
  // A link to `object` in another HDF5 file; a relative `file` is looked up from the folder of the
  // file holding the link (HDF5 tries that before the working directory).
  void create_external_link(std::string_view name, std::string_view file, std::string_view object) const;
  struct ExternalTarget {
    std::string file;    // as stored (relative to this file's folder, normally)
    std::string object;  // path inside it
  };
  std::optional<ExternalTarget> external_link(std::string_view name) const;  // empty: not an external link

  // Datasets: 1-D of length N, N x 3 for vectors, N x 4 for quaternions (w, x, y, z). `units`
  // (optional) is stored as the dataset's string attribute "units".
  void write_doubles(std::string_view name, std::span<const double> data, std::string_view units = {}) const;
  void write_int64s(std::string_view name, std::span<const std::int64_t> data, std::string_view units = {}) const;
  void write_uint32s(std::string_view name, std::span<const std::uint32_t> data) const;
  void write_uint8s(std::string_view name, std::span<const std::uint8_t> data) const;
  void write_vec3s(std::string_view name, std::span<const Vec3> data, std::string_view units = {}) const;
  void write_int3s(std::string_view name, std::span<const Int3> data) const;   // N x 3 int32
  void write_quaternions(std::string_view name, std::span<const Quaternion> data) const;  // N x 4 float64
  void write_strings(std::string_view name, const std::vector<std::string>& data) const;  // variable-length UTF-8
  // A stack of 2-D fields, layers x rows x columns of float32, deflate-compressed (HDF5's built-in
  // filter) in one chunk per layer: compact files of gridded results (analysis/field_history.h5).
  void write_float_stack(std::string_view name, const FloatStack& stack, std::string_view units = {}) const;

  // Readers check the rank and shape and convert the stored number type to the requested one
  // (so a file written by h5py with float32 or int32 columns reads too).
  std::vector<double> read_doubles(std::string_view name) const;
  std::vector<std::int64_t> read_int64s(std::string_view name) const;
  std::vector<std::uint32_t> read_uint32s(std::string_view name) const;
  std::vector<std::uint8_t> read_uint8s(std::string_view name) const;
  std::vector<Vec3> read_vec3s(std::string_view name) const;
  std::vector<Int3> read_int3s(std::string_view name) const;
  std::vector<Quaternion> read_quaternions(std::string_view name) const;
  std::vector<std::string> read_strings(std::string_view name) const;
  FloatStack read_float_stack(std::string_view name) const;  // any 3-D dataset of a convertible number type
  std::size_t dataset_length(std::string_view name) const;  // first dimension

  // Scalar attributes of this group.
  void set_double_attribute(std::string_view name, double value) const;
  void set_int_attribute(std::string_view name, std::int64_t value) const;
  void set_string_attribute(std::string_view name, std::string_view value) const;
  bool has_attribute(std::string_view name) const;
  double double_attribute(std::string_view name) const;
  std::int64_t int_attribute(std::string_view name) const;
  std::string string_attribute(std::string_view name) const;   // variable- or fixed-length strings
  std::vector<std::string> attribute_names() const;

  // "<file>: <path>/<name>" for messages.
  std::string describe(std::string_view name = {}) const;

 protected:
  Hdf5Group(std::string file, std::string path, Hdf5Handle handle)
      : file_(std::move(file)), path_(std::move(path)), handle_(std::move(handle)) {}
  Hdf5Group() = default;

  std::string file_;
  std::string path_;
  Hdf5Handle handle_;

 private:
  std::string child_path(std::string_view name) const;
};

// Two ways to write. Writers of trapdem's own files build the file in memory and then write its
// bytes with plain POSIX calls (create_in_memory / open_in_memory + write_image): a full disk is
// then an ordinary write error, whereas HDF5 1.10 left with a failed flush on a real file crashes
// at program exit. create() writes straight to disk (tests, small tools).
class Hdf5File : public Hdf5Group {
 public:
  static Hdf5File create(const std::filesystem::path& path);           // truncates
  // Both opens of an existing file check first that libhdf5 survives it (io/hdf5_probe).
  static Hdf5File open_read(const std::filesystem::path& path);
  // An empty file held in memory; `name` is what messages call it (normally the final path).
  static Hdf5File create_in_memory(const std::filesystem::path& name);
  // The file at `path` loaded into memory; changes stay in memory until write_image.
  static Hdf5File open_in_memory(const std::filesystem::path& path);

  // In-memory files: writes the complete file to `path` (created or truncated) and closes.
  // Throws FileError naming `path` and the system's reason (e.g. "No space left on device").
  void write_image(const std::filesystem::path& path);

  // Flushes and closes, throwing FileError if the data cannot be written. The destructor closes
  // too but cannot report a failure.
  void close();

 private:
  using Hdf5Group::Hdf5Group;
  bool written_here_ = false;  // created on disk by create(): close() notes it (io/hdf5_probe)
};

// Switches HDF5's automatic error printing off for this thread (idempotent).
void silence_hdf5_errors();

}  // namespace trapdem

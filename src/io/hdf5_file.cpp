#include "io/hdf5_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "io/hdf5_global_heap.hpp"
#include "io/hdf5_probe.hpp"

namespace trapdem {

namespace fs = std::filesystem;

namespace {

// The innermost description on HDF5's error stack (e.g. "No space left on device" from the
// file driver), so that our message carries the library's reason.
std::string hdf5_reason() {
  std::string deepest;
  auto walk = [](unsigned, const H5E_error2_t* err, void* data) -> herr_t {
    if (err && err->desc && *err->desc) *static_cast<std::string*>(data) = err->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, walk, &deepest);  // downward: from the API call to the cause
  H5Eclear2(H5E_DEFAULT);
  return deepest.empty() ? "HDF5 error" : deepest;
}

[[noreturn]] void fail(const std::string& where, std::string_view what) {
  throw FileError(fmt::format("{}: {} ({})", where, what, hdf5_reason()));
}

// Without fclose degree "strong", H5Fclose returns while groups or datasets are still open and
// the final flush (where a full disk shows) happens later, unchecked.
Hdf5Handle file_access_list() {
  Hdf5Handle fapl(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG);
  return fapl;
}

// A group's or dataset's creation properties without its modification time: HDF5 stamps each object
// by default, so two writes of the same data differed in a few bytes; without it a file is a
// function of its content (a re-analysis that changes nothing leaves a published file unchanged,
// and byte comparisons of outputs mean what they say).
Hdf5Handle untimed_creation_list(hid_t property_class) {
  Hdf5Handle list(H5Pcreate(property_class));
  H5Pset_obj_track_times(list.get(), false);
  return list;
}

Hdf5Handle string_type() {
  Hdf5Handle type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

struct Shape {
  int rank = 0;
  hsize_t dims[2] = {0, 0};
};

// A dataset's string attribute "units", when `units` is not empty.
void write_units(const Hdf5Group& g, std::string_view name, hid_t set, std::string_view units) {
  if (units.empty()) return;
  Hdf5Handle type = string_type();
  Hdf5Handle scalar(H5Screate(H5S_SCALAR));
  Hdf5Handle attr(H5Acreate2(set, "units", type.get(), scalar.get(), H5P_DEFAULT, H5P_DEFAULT));
  const std::string text(units);
  const char* ptr = text.c_str();
  if (!attr.valid() || H5Awrite(attr.get(), type.get(), &ptr) < 0) fail(g.describe(name), "cannot write the units attribute");
}

void write_dataset(const Hdf5Group& g, std::string_view name, hid_t file_type, hid_t memory_type, const void* data,
                   std::size_t rows, std::size_t columns, std::string_view units) {
  const std::string key(name);
  hsize_t dims[2] = {rows, columns};
  Hdf5Handle space(H5Screate_simple(columns == 0 ? 1 : 2, dims, nullptr));
  if (!space.valid()) fail(g.describe(name), "cannot create the dataspace");
  Hdf5Handle creation = untimed_creation_list(H5P_DATASET_CREATE);
  Hdf5Handle set(H5Dcreate2(g.id(), key.c_str(), file_type, space.get(), H5P_DEFAULT, creation.get(), H5P_DEFAULT));
  if (!set.valid()) fail(g.describe(name), "cannot create the dataset");
  if (rows > 0 && H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail(g.describe(name), "cannot write the dataset");
  write_units(g, name, set.get(), units);
}

// A dataset's in-memory size may exceed what the file stores for it: type widening (at most 8x,
// one byte to a double), compression (deflate, HDF5's built-in filter, packs at most 1032:1) or
// chunks never written (read as fill values). Beyond those, and above 64 MiB, the extent in the
// file is damaged, and reading it would allocate what the file cannot hold.
constexpr double kAlwaysReadableBytes = 64.0 * 1024 * 1024;

void check_dataset_memory(const Hdf5Group& g, std::string_view name, hid_t set, double bytes) {
  if (bytes <= kAlwaysReadableBytes) return;
  Hdf5Handle creation(H5Dget_create_plist(set));
  const bool filtered = creation.valid() && H5Pget_nfilters(creation.get()) > 0;
  const double stored = double(H5Dget_storage_size(set));
  const double limit = stored * (filtered ? 1032.0 : 8.0);
  if (bytes > limit)
    throw FileError(fmt::format("{}: its extent needs {:.3g} bytes in memory, but the file stores {:.3g} bytes for it "
                                "(expected at most {:.0f} times that{}): damaged dataset",
                                g.describe(name), bytes, stored, filtered ? 1032.0 : 8.0,
                                filtered ? ", deflate's ratio" : ""));
}

// Opens a dataset that holds its values.
Hdf5Handle open_stored_dataset(const Hdf5Group& g, std::string_view name) {
  const std::string key(name);
  if (!g.has(name)) throw FileError(fmt::format("{}: no such dataset", g.describe(name)));
  Hdf5Handle set(H5Dopen2(g.id(), key.c_str(), H5P_DEFAULT));
  if (!set.valid()) fail(g.describe(name), "cannot open the dataset");
  // A virtual dataset's values are read from other files, which the probe before the open did
  // not see (io/hdf5_probe); trapdem's files and h5py's ordinary ones hold their values.
  Hdf5Handle creation(H5Dget_create_plist(set.get()));
  if (creation.valid() && H5Pget_layout(creation.get()) == H5D_VIRTUAL)
    throw FileError(fmt::format("{}: a virtual dataset (its values are in other files): expected one that holds "
                                "its values", g.describe(name)));
  return set;
}

// Opens a dataset and checks that it is 1-D (columns == 0) or N x columns, and that N rows of
// `row_bytes` in memory agree with what the file stores (check_dataset_memory).
Hdf5Handle open_dataset(const Hdf5Group& g, std::string_view name, std::size_t columns, std::size_t& rows,
                        std::size_t row_bytes) {
  Hdf5Handle set = open_stored_dataset(g, name);
  Hdf5Handle space(H5Dget_space(set.get()));
  const int rank = H5Sget_simple_extent_ndims(space.get());
  hsize_t dims[H5S_MAX_RANK] = {};
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  const bool ok = columns == 0 ? rank == 1 : (rank == 2 && dims[1] == columns);
  if (!ok) {
    std::string found = "rank " + std::to_string(rank) + " (";
    for (int r = 0; r < rank; ++r) found += (r ? " x " : "") + std::to_string(dims[r]);
    found += ")";
    throw FileError(fmt::format("{}: expected {}, found a dataset of {}", g.describe(name),
                                columns == 0 ? std::string("a 1-D dataset") : fmt::format("an N x {} dataset", columns),
                                found));
  }
  check_dataset_memory(g, name, set.get(), double(dims[0]) * double(row_bytes));
  rows = dims[0];
  return set;
}

template <class T>
std::vector<T> read_dataset(const Hdf5Group& g, std::string_view name, hid_t memory_type, std::size_t columns) {
  std::size_t rows = 0;
  Hdf5Handle set = open_dataset(g, name, columns, rows, sizeof(T));
  std::vector<T> out(rows);
  if (rows > 0 && H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail(g.describe(name), "cannot read the dataset (is its number type convertible?)");
  return out;
}

// Opens an attribute that must hold exactly one value (a scalar or a one-element array): reading
// a larger one into a single value would write past it.
Hdf5Handle open_attribute(const Hdf5Group& g, std::string_view name) {
  const std::string key(name);
  if (!g.has_attribute(name))
    throw FileError(fmt::format("{}: no attribute '{}'", g.describe(), key));
  Hdf5Handle attr(H5Aopen(g.id(), key.c_str(), H5P_DEFAULT));
  if (!attr.valid()) fail(g.describe(), fmt::format("cannot open attribute '{}'", key));
  Hdf5Handle space(H5Aget_space(attr.get()));
  const hssize_t points = space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
  if (points != 1)
    throw FileError(fmt::format("{}: attribute '{}' holds {} values: expected one", g.describe(), key, points));
  return attr;
}

// Creates (replacing an existing one) a scalar attribute.
Hdf5Handle create_attribute(const Hdf5Group& g, std::string_view name, hid_t type) {
  const std::string key(name);
  if (H5Aexists(g.id(), key.c_str()) > 0) H5Adelete(g.id(), key.c_str());
  Hdf5Handle scalar(H5Screate(H5S_SCALAR));
  Hdf5Handle attr(H5Acreate2(g.id(), key.c_str(), type, scalar.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attr.valid()) fail(g.describe(), fmt::format("cannot create attribute '{}'", key));
  return attr;
}

// Reads a one-value string attribute of either kind HDF5 stores (variable length, as trapdem and
// h5py write, or fixed length, as numpy byte strings are), its storage checked first.
std::string read_string_attribute(hid_t attr, hid_t stored_type, const std::string& where) {
  if (H5Tget_class(stored_type) != H5T_STRING) throw FileError(where + ": expected a string");
  if (H5Tis_variable_str(stored_type) > 0) {
    check_global_heap_strings(attr, true, 1, where);
    Hdf5Handle type = string_type();
    char* ptr = nullptr;
    if (H5Aread(attr, type.get(), &ptr) < 0) fail(where, "cannot read the string");
    std::string out = ptr ? ptr : "";
    H5free_memory(ptr);
    return out;
  }
  // A fixed-length string: its declared size is what HDF5 copies out, so it must be the size the
  // attribute stores, and no larger than the file.
  const std::size_t size = H5Tget_size(stored_type);
  Hdf5Handle file(H5Iget_file_id(attr));
  hsize_t file_size = 0;
  if (!file.valid() || H5Fget_filesize(file.get(), &file_size) < 0) fail(where, "cannot tell the file's size");
  if (size == 0 || size > file_size || H5Aget_storage_size(attr) != size)
    throw FileError(fmt::format("{}: a fixed-length string of {} bytes stored in {} bytes of a file of {} bytes: "
                                "damaged attribute",
                                where, size, H5Aget_storage_size(attr), file_size));
  std::string buffer(size, '\0');
  Hdf5Handle type(H5Tcopy(stored_type));
  if (H5Aread(attr, type.get(), buffer.data()) < 0) fail(where, "cannot read the string");
  buffer.resize(std::strlen(buffer.c_str()));  // fixed-length strings are NUL- or space-padded
  while (!buffer.empty() && buffer.back() == ' ') buffer.pop_back();
  return buffer;
}

}  // namespace

void silence_hdf5_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// ---------------------------------------------------------------------------------------------
Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_;
    other.id_ = H5I_INVALID_HID;
  }
  return *this;
}

void Hdf5Handle::reset() {
  if (id_ < 0) return;
  switch (H5Iget_type(id_)) {
    case H5I_FILE: H5Fclose(id_); break;
    case H5I_GROUP: H5Gclose(id_); break;
    case H5I_DATASET: H5Dclose(id_); break;
    case H5I_DATASPACE: H5Sclose(id_); break;
    case H5I_DATATYPE: H5Tclose(id_); break;
    case H5I_ATTR: H5Aclose(id_); break;
    case H5I_GENPROP_LST: H5Pclose(id_); break;
    default: break;  // already closed (a strong file close takes its objects with it)
  }
  id_ = H5I_INVALID_HID;
}

hid_t Hdf5Handle::release() {
  const hid_t id = id_;
  id_ = H5I_INVALID_HID;
  return id;
}

// ---------------------------------------------------------------------------------------------
std::string Hdf5Group::child_path(std::string_view name) const {
  std::string out = path_;
  if (out.empty() || out.back() != '/') out += '/';
  out += name;
  return out;
}

std::string Hdf5Group::describe(std::string_view name) const {
  return fmt::format("{}: {}", file_, name.empty() ? path_ : child_path(name));
}

bool Hdf5Group::has(std::string_view name) const {
  const std::string key(name);
  const htri_t exists = H5Lexists(id(), key.c_str(), H5P_DEFAULT);
  // Negative: HDF5 could not tell (damaged metadata, or a path through a missing group), not "absent".
  if (exists < 0 && name.find('/') == std::string_view::npos)
    fail(describe(), fmt::format("cannot tell whether '{}' exists (the file is damaged)", name));
  return exists > 0;
}

Hdf5Group Hdf5Group::create_group(std::string_view name) const {
  const std::string key(name);
  Hdf5Handle creation = untimed_creation_list(H5P_GROUP_CREATE);
  Hdf5Handle g(H5Gcreate2(id(), key.c_str(), H5P_DEFAULT, creation.get(), H5P_DEFAULT));
  if (!g.valid()) fail(describe(name), "cannot create the group");
  return Hdf5Group(file_, child_path(name), std::move(g));
}

Hdf5Group Hdf5Group::group(std::string_view name) const {
  const std::string key(name);
  if (!has(name)) throw FileError(fmt::format("{}: no such group", describe(name)));
  Hdf5Handle g(H5Gopen2(id(), key.c_str(), H5P_DEFAULT));
  if (!g.valid()) fail(describe(name), "cannot open the group");
  return Hdf5Group(file_, child_path(name), std::move(g));
}

std::vector<std::string> Hdf5Group::children() const {
  std::vector<std::string> names;
  auto collect = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  // HDF5 1.10 lists a group whose links are messages in its header (compact storage: groups with
  // external links, as snapshots.h5's) by copying them into a table of the counted size; a link
  // message that does not decode ends the copy early, and the release then frees the unfilled
  // entries' garbage pointers (H5G__compact_build_table / H5G__link_release_table; the snapshot
  // fuzz target, one byte of a link message's flags changed). A name lookup decodes every link
  // message first and fails cleanly on a damaged one, so it goes first; the listing then finds
  // them decoded.
  if (H5Lexists(id(), "\x7f" "trapdem: no such link", H5P_DEFAULT) < 0)
    fail(describe(), "cannot read the group's links (damaged link messages?)");
  if (H5Literate(id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names) < 0)
    fail(describe(), "cannot list the group");
  return names;
}

void Hdf5Group::remove(std::string_view name) const {
  const std::string key(name);
  if (H5Ldelete(id(), key.c_str(), H5P_DEFAULT) < 0) fail(describe(name), "cannot remove the link");
}

void Hdf5Group::create_external_link(std::string_view name, std::string_view file, std::string_view object) const {
  const std::string key(name), target_file(file), target_object(object);
  if (H5Lcreate_external(target_file.c_str(), target_object.c_str(), id(), key.c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
    fail(describe(name), fmt::format("cannot create the link to {}:{}", target_file, target_object));
}

std::optional<Hdf5Group::ExternalTarget> Hdf5Group::external_link(std::string_view name) const {
  const std::string key(name);
  H5L_info_t info;
  if (H5Lget_info(id(), key.c_str(), &info, H5P_DEFAULT) < 0) fail(describe(name), "no such link");
  if (info.type != H5L_TYPE_EXTERNAL) return std::nullopt;
  std::vector<char> value(info.u.val_size);
  const char* file = nullptr;
  const char* object = nullptr;
  unsigned flags = 0;
  if (H5Lget_val(id(), key.c_str(), value.data(), value.size(), H5P_DEFAULT) < 0 ||
      H5Lunpack_elink_val(value.data(), value.size(), &flags, &file, &object) < 0)
    fail(describe(name), "cannot read the external link");
  return ExternalTarget{file, object};
}

void Hdf5Group::write_doubles(std::string_view name, std::span<const double> data, std::string_view units) const {
  write_dataset(*this, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), data.size(), 0, units);
}
void Hdf5Group::write_int64s(std::string_view name, std::span<const std::int64_t> data, std::string_view units) const {
  write_dataset(*this, name, H5T_STD_I64LE, H5T_NATIVE_INT64, data.data(), data.size(), 0, units);
}
void Hdf5Group::write_uint32s(std::string_view name, std::span<const std::uint32_t> data) const {
  write_dataset(*this, name, H5T_STD_U32LE, H5T_NATIVE_UINT32, data.data(), data.size(), 0, {});
}
void Hdf5Group::write_uint8s(std::string_view name, std::span<const std::uint8_t> data) const {
  write_dataset(*this, name, H5T_STD_U8LE, H5T_NATIVE_UINT8, data.data(), data.size(), 0, {});
}
void Hdf5Group::write_vec3s(std::string_view name, std::span<const Vec3> data, std::string_view units) const {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  write_dataset(*this, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), data.size(), 3, units);
}
void Hdf5Group::write_int3s(std::string_view name, std::span<const Int3> data) const {
  static_assert(sizeof(Int3) == 3 * sizeof(std::int32_t), "Int3 must be three packed int32");
  write_dataset(*this, name, H5T_STD_I32LE, H5T_NATIVE_INT32, data.data(), data.size(), 3, {});
}
void Hdf5Group::write_quaternions(std::string_view name, std::span<const Quaternion> data) const {
  static_assert(sizeof(Quaternion) == 4 * sizeof(double), "Quaternion must be four packed doubles (w, x, y, z)");
  write_dataset(*this, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), data.size(), 4, {});
}

void Hdf5Group::write_strings(std::string_view name, const std::vector<std::string>& data) const {
  std::vector<const char*> pointers;
  for (const std::string& s : data) pointers.push_back(s.c_str());
  Hdf5Handle type = string_type();
  write_dataset(*this, name, type.get(), type.get(), pointers.data(), pointers.size(), 0, {});
}

void Hdf5Group::write_float_stack(std::string_view name, const FloatStack& stack, std::string_view units) const {
  if (stack.value.size() != stack.layers * stack.rows * stack.columns)
    throw std::invalid_argument(fmt::format("write_float_stack {}: {} values for {} x {} x {}", describe(name),
                                            stack.value.size(), stack.layers, stack.rows, stack.columns));
  const std::string key(name);
  const hsize_t dims[3] = {stack.layers, stack.rows, stack.columns};
  Hdf5Handle space(H5Screate_simple(3, dims, nullptr));
  if (!space.valid()) fail(describe(name), "cannot create the dataspace");
  Hdf5Handle creation = untimed_creation_list(H5P_DATASET_CREATE);
  if (stack.value.size() > 0) {  // a chunk may not have a zero extent
    const hsize_t chunk[3] = {1, stack.rows, stack.columns};
    constexpr unsigned kDeflateLevel = 6;  // zlib's default: near its best ratio at a fraction of level 9's time
    if (H5Pset_chunk(creation.get(), 3, chunk) < 0 || H5Pset_deflate(creation.get(), kDeflateLevel) < 0)
      fail(describe(name), "cannot set the chunks and compression");
  }
  Hdf5Handle set(H5Dcreate2(id(), key.c_str(), H5T_IEEE_F32LE, space.get(), H5P_DEFAULT, creation.get(), H5P_DEFAULT));
  if (!set.valid()) fail(describe(name), "cannot create the dataset");
  if (!stack.value.empty() &&
      H5Dwrite(set.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, stack.value.data()) < 0)
    fail(describe(name), "cannot write the dataset");
  write_units(*this, name, set.get(), units);
}

FloatStack Hdf5Group::read_float_stack(std::string_view name) const {
  Hdf5Handle set = open_stored_dataset(*this, name);
  Hdf5Handle space(H5Dget_space(set.get()));
  hsize_t dims[H5S_MAX_RANK] = {};
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  if (rank != 3) throw FileError(fmt::format("{}: expected a 3-D dataset (layers x rows x columns), found rank {}",
                                             describe(name), rank));
  check_dataset_memory(*this, name, set.get(), double(dims[0]) * double(dims[1]) * double(dims[2]) * sizeof(float));
  FloatStack stack{dims[0], dims[1], dims[2], {}};
  stack.value.resize(stack.layers * stack.rows * stack.columns);
  if (!stack.value.empty() &&
      H5Dread(set.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, stack.value.data()) < 0)
    fail(describe(name), "cannot read the dataset (is its number type convertible?)");
  return stack;
}

std::vector<double> Hdf5Group::read_doubles(std::string_view name) const {
  return read_dataset<double>(*this, name, H5T_NATIVE_DOUBLE, 0);
}
std::vector<std::int64_t> Hdf5Group::read_int64s(std::string_view name) const {
  return read_dataset<std::int64_t>(*this, name, H5T_NATIVE_INT64, 0);
}
std::vector<std::uint32_t> Hdf5Group::read_uint32s(std::string_view name) const {
  return read_dataset<std::uint32_t>(*this, name, H5T_NATIVE_UINT32, 0);
}
std::vector<std::uint8_t> Hdf5Group::read_uint8s(std::string_view name) const {
  return read_dataset<std::uint8_t>(*this, name, H5T_NATIVE_UINT8, 0);
}
std::vector<Vec3> Hdf5Group::read_vec3s(std::string_view name) const {
  return read_dataset<Vec3>(*this, name, H5T_NATIVE_DOUBLE, 3);
}
std::vector<Int3> Hdf5Group::read_int3s(std::string_view name) const {
  return read_dataset<Int3>(*this, name, H5T_NATIVE_INT32, 3);
}
std::vector<Quaternion> Hdf5Group::read_quaternions(std::string_view name) const {
  return read_dataset<Quaternion>(*this, name, H5T_NATIVE_DOUBLE, 4);
}

std::vector<std::string> Hdf5Group::read_strings(std::string_view name) const {
  std::size_t rows = 0;
  // A row: its stored reference (at most 16 bytes) and the string's pointer.
  Hdf5Handle set = open_dataset(*this, name, 0, rows, 16 + sizeof(char*));
  Hdf5Handle stored(H5Dget_type(set.get()));
  if (H5Tget_class(stored.get()) != H5T_STRING || H5Tis_variable_str(stored.get()) <= 0)
    throw FileError(fmt::format("{}: expected variable-length strings", describe(name)));
  check_global_heap_strings(set.get(), false, rows, describe(name));
  Hdf5Handle type = string_type();
  std::vector<char*> pointers(rows, nullptr);
  if (rows > 0 && H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0)
    fail(describe(name), "cannot read the strings");
  std::vector<std::string> out;
  for (char* p : pointers) {
    out.emplace_back(p ? p : "");
    H5free_memory(p);
  }
  return out;
}

std::size_t Hdf5Group::dataset_length(std::string_view name) const {
  const std::string key(name);
  if (!has(name)) throw FileError(fmt::format("{}: no such dataset", describe(name)));
  Hdf5Handle set(H5Dopen2(id(), key.c_str(), H5P_DEFAULT));
  if (!set.valid()) fail(describe(name), "cannot open the dataset");
  Hdf5Handle space(H5Dget_space(set.get()));
  hsize_t dims[H5S_MAX_RANK] = {};
  const int rank = H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  return rank > 0 ? dims[0] : 1;
}

void Hdf5Group::set_double_attribute(std::string_view name, double value) const {
  Hdf5Handle attr = create_attribute(*this, name, H5T_IEEE_F64LE);
  if (H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail(describe(), fmt::format("cannot write attribute '{}'", name));
}

void Hdf5Group::set_int_attribute(std::string_view name, std::int64_t value) const {
  Hdf5Handle attr = create_attribute(*this, name, H5T_STD_I64LE);
  if (H5Awrite(attr.get(), H5T_NATIVE_INT64, &value) < 0)
    fail(describe(), fmt::format("cannot write attribute '{}'", name));
}

void Hdf5Group::set_string_attribute(std::string_view name, std::string_view value) const {
  Hdf5Handle type = string_type();
  Hdf5Handle attr = create_attribute(*this, name, type.get());
  const std::string text(value);
  const char* ptr = text.c_str();
  if (H5Awrite(attr.get(), type.get(), &ptr) < 0) fail(describe(), fmt::format("cannot write attribute '{}'", name));
}

bool Hdf5Group::has_attribute(std::string_view name) const {
  const std::string key(name);
  const htri_t exists = H5Aexists(id(), key.c_str());
  // Negative: HDF5 could not tell (damaged metadata), which is not "absent".
  if (exists < 0) fail(describe(), fmt::format("cannot tell whether attribute '{}' exists (the file is damaged)", name));
  return exists > 0;
}

double Hdf5Group::double_attribute(std::string_view name) const {
  Hdf5Handle attr = open_attribute(*this, name);
  double value = 0.0;
  if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail(describe(), fmt::format("attribute '{}' is not a number", name));
  return value;
}

std::int64_t Hdf5Group::int_attribute(std::string_view name) const {
  Hdf5Handle attr = open_attribute(*this, name);
  std::int64_t value = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_INT64, &value) < 0)
    fail(describe(), fmt::format("attribute '{}' is not an integer", name));
  return value;
}

std::string Hdf5Group::string_attribute(std::string_view name) const {
  Hdf5Handle attr = open_attribute(*this, name);
  Hdf5Handle stored(H5Aget_type(attr.get()));
  return read_string_attribute(attr.get(), stored.get(), fmt::format("{}: attribute '{}'", describe(), name));
}

std::vector<std::string> Hdf5Group::attribute_names() const {
  std::vector<std::string> names;
  auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  if (H5Aiterate2(id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names) < 0)
    fail(describe(), "cannot list the attributes");
  return names;
}

// ---------------------------------------------------------------------------------------------
Hdf5File Hdf5File::create(const fs::path& path) {
  silence_hdf5_errors();
  Hdf5Handle fapl = file_access_list();
  Hdf5Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()));
  if (!file.valid()) fail(path.string(), "cannot create the HDF5 file");
  Hdf5File out(path.string(), "/", std::move(file));
  out.written_here_ = true;
  return out;
}

Hdf5File Hdf5File::open_read(const fs::path& path) {
  silence_hdf5_errors();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw FileError(fmt::format("{}: no such file", path.string()));
  probe_hdf5_file(path);  // libhdf5 survives the file in a child process first
  Hdf5Handle fapl = file_access_list();
  Hdf5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get()));
  if (!file.valid()) fail(path.string(), "cannot open as an HDF5 file (damaged or not HDF5?)");
  return Hdf5File(path.string(), "/", std::move(file));
}

namespace {
// The core (memory) driver without a backing store: nothing reaches the disk through HDF5.
Hdf5Handle memory_access_list() {
  Hdf5Handle fapl = file_access_list();
  H5Pset_fapl_core(fapl.get(), 4 << 20, 0);  // grow in 4 MiB steps
  return fapl;
}
}  // namespace

Hdf5File Hdf5File::create_in_memory(const fs::path& name) {
  silence_hdf5_errors();
  Hdf5Handle fapl = memory_access_list();
  Hdf5Handle file(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()));
  if (!file.valid()) fail(name.string(), "cannot create the HDF5 file in memory");
  return Hdf5File(name.string(), "/", std::move(file));
}

Hdf5File Hdf5File::open_in_memory(const fs::path& path) {
  silence_hdf5_errors();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw FileError(fmt::format("{}: no such file", path.string()));
  probe_hdf5_file(path);
  Hdf5Handle fapl = memory_access_list();
  Hdf5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, fapl.get()));
  if (!file.valid()) fail(path.string(), "cannot load the HDF5 file (damaged or not HDF5?)");
  return Hdf5File(path.string(), "/", std::move(file));
}

void Hdf5File::write_image(const fs::path& path) {
  if (!handle_.valid()) throw FileError(fmt::format("{}: the file is already closed", file_));
  if (H5Fflush(id(), H5F_SCOPE_GLOBAL) < 0) fail(file_, "cannot finish the file in memory");
  const ssize_t size = H5Fget_file_image(id(), nullptr, 0);
  if (size < 0) fail(file_, "cannot take the file's image (was it opened in memory?)");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(id(), image.data(), image.size()) != size) fail(file_, "cannot take the file's image");
  close();

  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw FileError(fmt::format("cannot create {}: {}", path.string(), std::strerror(errno)));
  std::size_t done = 0;
  while (done < image.size()) {
    const ssize_t n = ::write(fd, image.data() + done, image.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      throw FileError(fmt::format("writing {} failed after {} of {} bytes: {}", path.string(), done, image.size(),
                                  std::strerror(err)));
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) throw FileError(fmt::format("writing {} failed: {}", path.string(), std::strerror(errno)));
  note_hdf5_file_written(path);
}

void Hdf5File::close() {
  if (!handle_.valid()) return;
  const hid_t id = handle_.release();
  if (H5Fflush(id, H5F_SCOPE_LOCAL) < 0) {
    H5Fclose(id);
    fail(file_, "cannot write the file's data to disk");
  }
  if (H5Fclose(id) < 0) fail(file_, "closing the file failed");
  if (written_here_) note_hdf5_file_written(file_);
}

}  // namespace trapdem

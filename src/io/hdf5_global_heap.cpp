#include "io/hdf5_global_heap.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/hdf5_file.hpp"

namespace trapdem {

namespace {

// The opaque type a stored reference is read into (its tag tells our conversion it is wanted).
constexpr const char* kStoredTag = "trapdem: a variable-length string as stored";

// A soft conversion from a variable-length string, as HDF5 hands it over from the file (length,
// collection address, object index: 4 + sizeof_addr + 4 bytes), to our opaque type of the same
// size. HDF5 copies the stored element into the conversion buffer before converting (H5A__read,
// H5D__scatgath_read), so converting "in place, unchanged" yields the stored bytes and the heap
// is never touched.
herr_t keep_stored_form(hid_t source, hid_t destination, H5T_cdata_t* cdata, std::size_t, std::size_t, std::size_t,
                        void*, void*, hid_t) {
  switch (cdata->command) {
    case H5T_CONV_INIT: {
      if (H5Tis_variable_str(source) <= 0 || H5Tget_class(destination) != H5T_OPAQUE) return -1;
      char* tag = H5Tget_tag(destination);
      const bool ours = tag != nullptr && std::strcmp(tag, kStoredTag) == 0;
      H5free_memory(tag);
      if (!ours || H5Tget_size(source) != H5Tget_size(destination)) return -1;
      cdata->need_bkg = H5T_BKG_NO;
      return 0;
    }
    case H5T_CONV_CONV:
    case H5T_CONV_FREE: return 0;
    default: return -1;
  }
}

void register_conversion() {
  static const bool registered = [] {
    Hdf5Handle text(H5Tcopy(H5T_C_S1));
    H5Tset_size(text.get(), H5T_VARIABLE);
    Hdf5Handle opaque(H5Tcreate(H5T_OPAQUE, 16));
    H5Tset_tag(opaque.get(), kStoredTag);
    return H5Tregister(H5T_PERS_SOFT, "trapdem stored string", text.get(), opaque.get(), keep_stored_form) >= 0;
  }();
  if (!registered) throw FileError("HDF5: cannot register the stored-string conversion");
}

std::uint64_t little_endian(const std::uint8_t* p, std::size_t bytes) {
  std::uint64_t value = 0;
  for (std::size_t k = 0; k < bytes; ++k) value |= std::uint64_t(p[k]) << (8 * k);
  return value;
}

constexpr std::uint64_t align8(std::uint64_t n) { return (n + 7) / 8 * 8; }  // H5HG_ALIGN

// The bytes of an open file as HDF5 sees them: the file itself (sec2 driver, through HDF5's own
// descriptor) or, for a file held in memory (core driver), a copy of its image.
class FileBytes {
 public:
  explicit FileBytes(hid_t file) {
    Hdf5Handle access(H5Fget_access_plist(file));
    void* handle = nullptr;
    if (H5Pget_driver(access.get()) == H5FD_SEC2 && H5Fget_vfd_handle(file, access.get(), &handle) >= 0 && handle) {
      fd_ = *static_cast<int*>(handle);
      struct stat st {};
      if (::fstat(fd_, &st) == 0) size_ = std::uint64_t(st.st_size);
      return;
    }
    unsigned intent = 0;
    if (H5Fget_intent(file, &intent) >= 0 && (intent & H5F_ACC_RDWR)) H5Fflush(file, H5F_SCOPE_LOCAL);
    const ssize_t size = H5Fget_file_image(file, nullptr, 0);
    if (size <= 0) return;
    image_.resize(std::size_t(size));
    if (H5Fget_file_image(file, image_.data(), image_.size()) != size) image_.clear();
    size_ = image_.size();
  }

  std::uint64_t size() const { return size_; }

  // Bytes [offset, offset + n); false if not all of them are in the file.
  bool read(std::uint64_t offset, std::size_t n, std::uint8_t* out) const {
    if (offset > size_ || n > size_ - offset) return false;
    if (fd_ < 0) {
      std::memcpy(out, image_.data() + offset, n);
      return true;
    }
    std::size_t done = 0;
    while (done < n) {
      const ssize_t got = ::pread(fd_, out + done, n - done, off_t(offset + done));
      if (got <= 0) return false;
      done += std::size_t(got);
    }
    return true;
  }

 private:
  int fd_ = -1;
  std::vector<std::uint8_t> image_;
  std::uint64_t size_ = 0;
};

// The objects of one global heap collection, by index: their sizes in bytes.
using HeapObjects = std::map<unsigned, std::uint64_t>;

// Decodes the collection at file offset `offset` as H5HG__cache_heap_deserialize does (HDF5 1.10),
// refusing what would make that loop run for ever, allocate beyond the file or leave an object
// past the collection's end.
HeapObjects walk_collection(const FileBytes& bytes, std::uint64_t offset, std::size_t size_bytes,
                            const std::string& where) {
  auto damaged = [&](const std::string& what) {
    return FileError(fmt::format("{}: damaged string storage: the global heap collection at byte {} {}; the file "
                                 "cannot be read (restore a copy or write it again)",
                                 where, offset, what));
  };
  const std::size_t header = align8(8 + size_bytes);        // "GCOL", version, reserved, size
  const std::size_t object_header = 8 + size_bytes;         // index, references, reserved, size
  std::vector<std::uint8_t> data(header);
  if (!bytes.read(offset, header, data.data()))
    throw damaged(fmt::format("lies outside the file ({} bytes)", bytes.size()));
  if (std::memcmp(data.data(), "GCOL", 4) != 0) throw damaged("has no GCOL signature");
  if (data[4] != 1) throw damaged(fmt::format("has version {} (expected 1)", data[4]));
  const std::uint64_t size = little_endian(data.data() + 8, size_bytes);
  if (size < header || size > bytes.size() - offset)
    throw damaged(fmt::format("claims {} bytes: expected at least {} and at most the {} bytes left in the file", size,
                              header, bytes.size() - offset));
  data.resize(std::size_t(size));
  if (!bytes.read(offset, data.size(), data.data())) throw damaged("cannot be read");

  HeapObjects objects;
  std::uint64_t p = header;
  while (p < size) {
    if (p + object_header > size) {  // a tail too short for an object header: free space
      objects[0] = size - p;
      break;
    }
    const std::uint8_t* o = data.data() + p;
    const unsigned index = unsigned(o[0]) | unsigned(o[1]) << 8;
    const std::uint64_t object_size = little_endian(o + 8, size_bytes);
    // An object's space: its header and its data padded to 8 bytes; the free-space object 0's
    // size already counts both.
    const std::uint64_t need = index == 0 ? object_size
                               : object_size > size ? size + 1
                                                    : object_header + align8(object_size);
    if (need == 0 || need > size - p)
      throw damaged(fmt::format("holds object {} of {} bytes at offset {}, which does not fit in its {} bytes", index,
                                object_size, p, size));
    objects[index] = object_size;
    p += need;
  }
  return objects;
}

}  // namespace

void check_global_heap_strings(hid_t object, bool attribute, std::size_t count, const std::string& where) {
  if (count == 0) return;
  register_conversion();
  Hdf5Handle file(H5Iget_file_id(object));
  Hdf5Handle creation(H5Fget_create_plist(file.get()));
  std::size_t address_bytes = 0, size_bytes = 0;
  hsize_t base = 0;
  if (!file.valid() || !creation.valid() || H5Pget_sizes(creation.get(), &address_bytes, &size_bytes) < 0 ||
      H5Pget_userblock(creation.get(), &base) < 0)
    throw FileError(fmt::format("{}: cannot read the file's address and length sizes", where));
  if (address_bytes < 2 || address_bytes > 8 || size_bytes < 2 || size_bytes > 8)
    throw FileError(fmt::format("{}: addresses of {} bytes and lengths of {} bytes are not supported (at most 8)",
                                where, address_bytes, size_bytes));

  // The stored references: sequence length (uint32), collection address, object index (uint32).
  const std::size_t reference = 4 + address_bytes + 4;
  if (attribute && H5Aget_storage_size(object) != hsize_t(count) * reference)
    throw FileError(fmt::format("{}: holds {} bytes for {} string(s): expected {} bytes", where,
                                H5Aget_storage_size(object), count, count * reference));
  Hdf5Handle opaque(H5Tcreate(H5T_OPAQUE, reference));
  H5Tset_tag(opaque.get(), kStoredTag);
  std::vector<std::uint8_t> stored(count * reference);
  const herr_t rc = attribute ? H5Aread(object, opaque.get(), stored.data())
                              : H5Dread(object, opaque.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, stored.data());
  if (rc < 0) {
    H5Eclear2(H5E_DEFAULT);
    throw FileError(fmt::format("{}: cannot read the stored string references", where));
  }

  const FileBytes bytes(file.get());
  std::map<std::uint64_t, HeapObjects> collections;
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint8_t* r = stored.data() + k * reference;
    const std::uint64_t length = little_endian(r, 4);
    const std::uint64_t address = little_endian(r + 4, address_bytes);
    const unsigned index = unsigned(little_endian(r + 4 + address_bytes, 4));
    if (address == 0) continue;  // a null string: HDF5 reads no heap
    const std::string which = count == 1 ? where : fmt::format("{} (string {})", where, k);
    if (address > bytes.size() || base > bytes.size() - address)
      throw FileError(fmt::format("{}: damaged string storage: its text is said to be at byte {}, beyond the file's "
                                  "{} bytes",
                                  which, address, bytes.size()));
    auto found = collections.find(address);
    if (found == collections.end())
      found = collections.emplace(address, walk_collection(bytes, base + address, size_bytes, which)).first;
    const auto object = found->second.find(index);
    if (index == 0 || object == found->second.end())
      throw FileError(fmt::format("{}: damaged string storage: object {} is not in the global heap collection at "
                                  "byte {}",
                                  which, index, base + address));
    if (object->second != length)
      throw FileError(fmt::format("{}: damaged string storage: a string of {} bytes whose text in the global heap "
                                  "holds {} bytes",
                                  which, length, object->second));
  }
}

}  // namespace trapdem

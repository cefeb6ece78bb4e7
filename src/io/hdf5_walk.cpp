#include "io/hdf5_walk.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "io/hdf5_file.hpp"
#include "io/hdf5_global_heap.hpp"

namespace trapdem {

std::optional<FileIdentity> identity_of(const std::filesystem::path& path) {
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0) return std::nullopt;
  return FileIdentity{std::uint64_t(s.st_dev), std::uint64_t(s.st_ino), std::int64_t(s.st_size),
                      std::int64_t(s.st_mtim.tv_sec) * 1000000000 + s.st_mtim.tv_nsec,
                      std::int64_t(s.st_ctim.tv_sec) * 1000000000 + s.st_ctim.tv_nsec};
}

namespace {

// Values read whole up to this size; beyond it, the first element only (the reader's whole read
// of a contiguous dataset is one block HDF5 checks against the file's end; a chunked one's index
// is walked whole here).
constexpr std::size_t kWholeReadBytes = std::size_t(1) << 20;
// Variable-length string references checked up to this count (16 bytes each in memory).
constexpr hssize_t kMaxCheckedStrings = hssize_t(1) << 22;
// External link values read up to this size (a file name and an object path).
constexpr std::size_t kMaxLinkValue = 1 << 16;

struct Link {
  std::string name;
  H5L_type_t type;
};

class Walker {
 public:
  explicit Walker(const Hdf5WalkSink& sink) : sink_(sink) {}

  void walk(const std::filesystem::path& path) {
    Hdf5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!file.valid()) return;
    top_ = path.string();
    pending_.push_back({std::make_shared<Hdf5Handle>(std::move(file)), "/", "/"});
    while (!pending_.empty()) {
      Pending next = std::move(pending_.back());
      pending_.pop_back();
      visit(next);
    }
  }

 private:
  // An object still to visit: its link `name` in the open location `parent`, `path` from the root.
  struct Pending {
    std::shared_ptr<Hdf5Handle> parent;
    std::string name;
    std::string path;
  };

  void visit(const Pending& p) {
    const std::string where = top_ + ": " + p.path;
    sink_.at(where);
    auto object = std::make_shared<Hdf5Handle>(H5Oopen(p.parent->get(), p.name.c_str(), H5P_DEFAULT));
    if (!object->valid()) return;
    // Each call below stands alone: one that fails (an HDF5 error) does not stop the others, as
    // a reader may well make them in another order. Only an object HDF5 cannot even locate is
    // left without its links followed (it could not be told from one already visited).
    H5O_info_t info{};
    const bool located = H5Oget_info2(object->get(), &info, H5O_INFO_BASIC) >= 0;
    if (located && !seen_.insert({info.fileno, info.addr}).second) return;  // a second link, or a cycle
    if (located && !enter_file(object->get(), info.fileno)) return;
    H5O_info_t all{};
    H5Oget_info2(object->get(), &all, H5O_INFO_ALL);
    attributes(object->get(), where);
    const H5I_type_t type = H5Iget_type(object->get());
    if (type == H5I_GROUP) group(object, p.path, located ? std::optional<unsigned long>(info.fileno) : std::nullopt);
    else if (type == H5I_DATASET) dataset(object->get(), where);
  }

  // The object's file: new ones are announced (and skipped if the sink says so).
  bool enter_file(hid_t object, unsigned long fileno) {
    const auto known = files_.find(fileno);
    if (known != files_.end()) return known->second.walk;
    const ssize_t length = H5Fget_name(object, nullptr, 0);
    std::string name(length > 0 ? std::size_t(length) : 0, '\0');
    if (length > 0) H5Fget_name(object, name.data(), name.size() + 1);
    const std::optional<FileIdentity> identity = identity_of(name);
    // A file met again after HDF5 closed it (a new file number) is not walked twice: external
    // links that lead round in a circle end here.
    const bool again = identity && !entered_.insert(*identity).second;
    const bool walk = !again && (!identity || sink_.enter_file(name, *identity));
    files_[fileno] = {name, identity, walk};
    return walk;
  }

  void group(const std::shared_ptr<Hdf5Handle>& g, const std::string& path, std::optional<unsigned long> fileno) {
    H5G_info_t info{};
    H5Gget_info(g->get(), &info);
    // As Hdf5Group::children: a name lookup decodes every link message and fails cleanly on a
    // damaged one, which the listing would not survive (nor does the reader list it then).
    if (H5Lexists(g->get(), "\x7f" "trapdem: no such link", H5P_DEFAULT) < 0) return;
    std::vector<Link> links;
    auto collect = [](hid_t, const char* name, const H5L_info_t* link, void* data) -> herr_t {
      static_cast<std::vector<Link>*>(data)->push_back({name, link->type});
      return 0;
    };
    H5Literate(g->get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &links);  // those listed until a failure
    if (!fileno) return;
    for (const Link& link : links) {
      H5Lexists(g->get(), link.name.c_str(), H5P_DEFAULT);
      if (link.type == H5L_TYPE_EXTERNAL) {
        if (const auto& file = files_[*fileno]; file.identity) sink_.links_out(*file.identity);
        external_value(g->get(), link.name);
      }
      if (link.type == H5L_TYPE_HARD || link.type == H5L_TYPE_SOFT || link.type == H5L_TYPE_EXTERNAL)
        pending_.push_back({g, link.name, path == "/" ? "/" + link.name : path + "/" + link.name});
    }
  }

  // An external link's value, as Hdf5Group::external_link reads it.
  void external_value(hid_t g, const std::string& name) {
    H5L_info_t info{};
    if (H5Lget_info(g, name.c_str(), &info, H5P_DEFAULT) < 0 || info.u.val_size > kMaxLinkValue) return;
    std::vector<char> value(info.u.val_size);
    unsigned flags = 0;
    const char* file = nullptr;
    const char* object = nullptr;
    if (H5Lget_val(g, name.c_str(), value.data(), value.size(), H5P_DEFAULT) >= 0)
      H5Lunpack_elink_val(value.data(), value.size(), &flags, &file, &object);
  }

  void attributes(hid_t object, const std::string& where) {
    std::vector<std::string> names;
    auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
      static_cast<std::vector<std::string>*>(data)->emplace_back(name);
      return 0;
    };
    if (H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names) < 0) return;
    for (const std::string& name : names) {
      const std::string at = where + ": attribute '" + name + "'";
      sink_.at(at);
      if (H5Aexists(object, name.c_str()) <= 0) continue;
      Hdf5Handle attr(H5Aopen(object, name.c_str(), H5P_DEFAULT));
      if (!attr.valid()) continue;
      Hdf5Handle type(H5Aget_type(attr.get()));
      Hdf5Handle space(H5Aget_space(attr.get()));
      if (!type.valid() || !space.valid()) continue;
      const hssize_t n = H5Sget_simple_extent_npoints(space.get());
      values(attr.get(), true, type.get(), n, n, H5Aget_storage_size(attr.get()), at);
    }
  }

  void dataset(hid_t set, const std::string& where) {
    Hdf5Handle creation(H5Dget_create_plist(set));
    if (creation.valid()) {
      H5Pget_nfilters(creation.get());
      const H5D_layout_t layout = H5Pget_layout(creation.get());
      if (layout == H5D_VIRTUAL) return;  // its data is in other files; the readers refuse it
      if (layout == H5D_CHUNKED) {
        hsize_t chunks = 0;
        H5Dget_num_chunks(set, H5S_ALL, &chunks);  // walks the whole chunk index
      }
    }
    const hsize_t stored = H5Dget_storage_size(set);
    Hdf5Handle type(H5Dget_type(set));
    Hdf5Handle space(H5Dget_space(set));
    if (!type.valid() || !space.valid()) return;
    const hssize_t n = H5Sget_simple_extent_npoints(space.get());
    if (n <= 0) return;
    // The element count read: all, or the first element when all would exceed kWholeReadBytes.
    const std::size_t element = std::max<std::size_t>(H5Tget_size(type.get()), 16);
    hssize_t read = n;
    if (double(n) * double(element) > double(kWholeReadBytes)) {
      const int rank = H5Sget_simple_extent_ndims(space.get());
      if (rank <= 0) return;
      std::vector<hsize_t> start(std::size_t(rank), 0), count(std::size_t(rank), 1);
      if (H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr) < 0) return;
      read = 1;
    }
    file_space_ = space.get();
    values(set, false, type.get(), n, read, stored, where);
    file_space_ = H5S_ALL;
  }

  // Reads `read` of the object's `n` values into their native form (numbers, strings of either
  // kind; other classes are left alone: the readers refuse them before reading). A dataset reads
  // the selection in file_space_.
  void values(hid_t object, bool attribute, hid_t stored, hssize_t n, hssize_t read, hsize_t storage,
              const std::string& where) {
    if (n <= 0 || read <= 0) return;
    const H5T_class_t kind = H5Tget_class(stored);
    Hdf5Handle memory;
    if (kind == H5T_INTEGER || kind == H5T_FLOAT) {
      memory = Hdf5Handle(H5Tget_native_type(stored, H5T_DIR_DEFAULT));
    } else if (kind == H5T_STRING && H5Tis_variable_str(stored) > 0) {
      if (n > kMaxCheckedStrings) return;
      try {
        check_global_heap_strings(object, attribute, std::size_t(n), where);
      } catch (const FileError&) {
        return;  // the reader refuses it with this message before reading
      }
      memory = Hdf5Handle(H5Tcopy(H5T_C_S1));
      H5Tset_size(memory.get(), H5T_VARIABLE);
      H5Tset_cset(memory.get(), H5Tget_cset(stored));
    } else if (kind == H5T_STRING) {
      // Fixed-length: HDF5 copies the declared size per element, which must be what is stored.
      if (double(H5Tget_size(stored)) * double(n) > double(storage)) return;
      memory = Hdf5Handle(H5Tcopy(stored));
    } else {
      return;
    }
    if (!memory.valid()) return;
    const std::size_t size = H5Tget_size(memory.get());
    if (size == 0 || double(size) * double(read) > double(kWholeReadBytes)) return;
    std::vector<unsigned char> buffer(size * std::size_t(read));
    const bool variable = H5Tis_variable_str(memory.get()) > 0;
    herr_t status;
    if (attribute) {
      status = H5Aread(object, memory.get(), buffer.data());
    } else {
      const hsize_t count = hsize_t(read);
      Hdf5Handle selected(H5Screate_simple(1, &count, nullptr));
      status = H5Dread(object, memory.get(), read == n ? H5S_ALL : selected.get(), read == n ? H5S_ALL : file_space_,
                       H5P_DEFAULT, buffer.data());
    }
    if (status >= 0 && variable) {
      for (hssize_t k = 0; k < read; ++k) {
        char* text = nullptr;
        std::memcpy(&text, buffer.data() + std::size_t(k) * sizeof(char*), sizeof(char*));
        H5free_memory(text);
      }
    }
  }

  struct FileSeen {
    std::string name;
    std::optional<FileIdentity> identity;
    bool walk = true;
  };

  const Hdf5WalkSink& sink_;
  std::vector<Pending> pending_;
  std::set<std::pair<unsigned long, haddr_t>> seen_;
  std::map<unsigned long, FileSeen> files_;  // by HDF5's number of the open file
  std::set<FileIdentity> entered_;
  std::string top_;  // the file walked, as messages name it (objects by their path from its root)
  hid_t file_space_ = H5S_ALL;
};

}  // namespace

void walk_hdf5_file(const std::filesystem::path& path, const Hdf5WalkSink& sink) {
  silence_hdf5_errors();
  Walker(sink).walk(path);
}

}  // namespace trapdem

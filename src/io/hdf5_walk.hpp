#pragma once
// What the HDF5 probe's child process touches in a file (io/hdf5_probe): every object reachable
// from the root group, through hard, soft and external links (the snapshot index reaches each
// snapshot's own file that way), and of each object what trapdem's readers may ask libhdf5 for:
// a group's info and links (a name lookup first, then the listing, as Hdf5Group::children does),
// every attribute with its values, a dataset's dataspace, type, creation properties, storage
// size, its whole chunk index, and its values (all of them up to 1 MiB, else the first element).
// Variable-length strings are checked (io/hdf5_global_heap) before they are read, as the readers
// do. HDF5's own errors are passed over: the reader meets them again and names them.
#include <sys/types.h>

#include <compare>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace trapdem {

// A file as it is on disk now: another identity means another or a changed file (unless it
// changed within the file system's timestamp granularity: io/hdf5_probe remembers only files
// whose times are older than that).
struct FileIdentity {
  std::uint64_t device = 0;
  std::uint64_t inode = 0;
  std::int64_t size = 0;
  std::int64_t modified_ns = 0;  // st_mtim, since the epoch
  std::int64_t changed_ns = 0;   // st_ctim (a rename, a rewrite in place)
  auto operator<=>(const FileIdentity&) const = default;
};
std::optional<FileIdentity> identity_of(const std::filesystem::path& path);  // empty: cannot stat

struct Hdf5WalkSink {
  // A file entered (the first, or one an external link reaches), as HDF5 named it when it opened
  // it. Returns false to pass over its contents (it passed a probe before and is unchanged).
  std::function<bool(const std::string& file, const FileIdentity&)> enter_file;
  // The file holds an external link (so its contents depend on other files too).
  std::function<void(const FileIdentity&)> links_out;
  // Where the walk is ("<file>: <path inside>"), before each object is touched.
  std::function<void(const std::string& where)> at;
};

void walk_hdf5_file(const std::filesystem::path& path, const Hdf5WalkSink& sink);

}  // namespace trapdem

#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace fs = std::filesystem;

namespace {

// Unique within the process (counter) and across processes sharing the folder (pid).
fs::path temporary_sibling(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  const std::string name = fmt::format(".{}.tmp-{}-{}", path.filename().string(), ::getpid(), counter++);
  return path.parent_path() / name;
}

fs::path folder_of(const fs::path& path) {
  return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

// fsync of the folder makes the rename itself durable (POSIX leaves it to the folder's metadata).
void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // some file systems refuse; the rename has happened, which is what matters
  ::fsync(fd);
  ::close(fd);
}

void check_folder(const fs::path& path) {
  const fs::path folder = folder_of(path);
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw FileError(fmt::format("cannot write {}: the folder {} does not exist", path.string(), folder.string()));
}

void move_into_place(const fs::path& temporary, const fs::path& path) {
  sync_file(temporary);
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    throw FileError(fmt::format("cannot write {}: renaming the finished temporary {} failed: {}", path.string(),
                                temporary.string(), std::strerror(errno)));
  sync_folder(folder_of(path));
}

void produce_and_move(const fs::path& path, const fs::path& temporary,
                      const std::function<void(const fs::path&)>& produce) {
  try {
    produce(temporary);
    move_into_place(temporary, path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    try {
      throw;
    } catch (const InputError&) {
      throw;
    } catch (const SimulationError&) {
      throw;
    } catch (const std::exception& e) {
      const std::string what = e.what();
      // Messages that already name the target are passed on as they are.
      if (what.find(path.string()) != std::string::npos) throw FileError(what);
      throw FileError(fmt::format("cannot write {}: {} (the previous file, if any, is unchanged)", path.string(), what));
    }
  }
}

}  // namespace

void sync_file(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) throw FileError(fmt::format("cannot open {} to sync it: {}", path.string(), std::strerror(errno)));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw FileError(fmt::format("cannot sync {} to disk: {}", path.string(), std::strerror(err)));
}

void write_atomically(const fs::path& path, const std::function<void(const fs::path& temporary)>& write) {
  check_folder(path);
  produce_and_move(path, temporary_sibling(path), write);
}

void write_text_atomically(const fs::path& path, std::string_view text) {
  write_atomically(path, [&](const fs::path& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw FileError(fmt::format("cannot create {}: {}", temporary.string(), std::strerror(errno)));
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) throw FileError(fmt::format("writing {} failed: {}", temporary.string(), std::strerror(errno)));
  });
}

void modify_atomically(const fs::path& path, const std::function<void(const fs::path& temporary)>& modify) {
  check_folder(path);
  const fs::path temporary = temporary_sibling(path);
  produce_and_move(path, temporary, [&](const fs::path& tmp) {
    std::error_code ec;
    if (fs::exists(path, ec)) {
      fs::copy_file(path, tmp, fs::copy_options::overwrite_existing, ec);
      if (ec) throw FileError(fmt::format("copying {} to {} failed: {}", path.string(), tmp.string(), ec.message()));
    }
    modify(tmp);
  });
}

}  // namespace trapdem

#pragma once
// Atomic replacement of a file: write a temporary sibling, fsync it, rename it over the target,
// fsync the folder. A crash, a full disk or any exception thrown while writing leaves the previous
// file (if any) untouched; readers never see a half-written file under the real name.
#include <filesystem>
#include <functional>
#include <string_view>

#include "core/errors.hpp"

namespace trapdem {

// Calls write(temporary_path) to produce the content, then moves it into place at `path`.
// The temporary lives in the same folder (rename is only atomic within one file system) and is
// named ".<name>.tmp-<pid>-<n>". On failure the temporary is removed and FileError is thrown
// naming `path` and the cause; an exception from `write` is rethrown as FileError with the path
// prepended (InputError and SimulationError pass through unchanged).
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temporary)>& write);

// write_atomically for a text (or binary) blob.
void write_text_atomically(const std::filesystem::path& path, std::string_view text);

// Like write_atomically, but the temporary starts as a copy of `path` (when it exists), so that
// `modify` can append to it (the snapshot file grows this way). The original stays in place until
// the modified copy is complete and synced.
void modify_atomically(const std::filesystem::path& path,
                       const std::function<void(const std::filesystem::path& temporary)>& modify);

// Flushes a written file's data to the disk (fsync). Throws FileError naming the path.
void sync_file(const std::filesystem::path& path);

}  // namespace trapdem

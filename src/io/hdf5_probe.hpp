#pragma once
// HDF5 files from users read behind a probe in a child process (issue 14). libhdf5 1.10 trusts the
// bytes of a file: the fuzzing of our readers found one damaged structure after another that made
// it loop for ever, allocate terabytes or read through a wild pointer (e.g. one byte of a group's
// link-info message giving a fractal-heap address near 2^64: H5G__obj_get_linfo -> H5B2_open ->
// H5F__accum_read copies from a null pointer), and several of them lie where no public HDF5 call
// lets us look first. Checking finding by finding would not end, so before the process opens a
// user's file, a forked child opens it and touches everything a reader may touch (io/hdf5_walk):
// if libhdf5 crashes, hangs or runs away with memory there, the child dies, not the program, and
// the reader gets a FileError naming the file and what happened instead of a crash.
//
// The child: one thread (fork copies only the caller's), core dumps off, the signal handlers of
// the program (and of sanitizers, libFuzzer, GoogleTest) reset so that a crash is a plain signal,
// CPU time and (in builds without AddressSanitizer, whose shadow memory an address-space limit
// would forbid) address space limited, leaving with _exit (no atexit handler: HDF5's would flush
// the parent's open files). The parent waits with a wall-clock limit and kills it on expiry.
// Under MPI only rank 0 reads user files (experiment/folder_run's on_root); OpenMP's threads are
// idle between parallel regions, where the readers run.
//
// A file that passed is remembered by its identity (device, inode, size, modification and change
// times; with the files its external links reach), so reading the same unchanged file again costs
// a stat; so is a file the process wrote itself (note_hdf5_file_written).
#include <chrono>
#include <filesystem>

namespace trapdem {

struct Hdf5ProbeLimits {
  std::chrono::milliseconds wall{30000};   // the child is killed after this (a hang in libhdf5)
  std::chrono::seconds cpu{20};            // RLIMIT_CPU: SIGXCPU, then SIGKILL one second later
  std::size_t memory_bytes = std::size_t(2) << 30;  // RLIMIT_AS above what the process maps already
  // A file rewritten in place within its file system's timestamp granularity (milliseconds, whole
  // seconds on some) keeps its identity: files changed less than this before a probe are probed
  // again next time (as git treats its "racily clean" entries).
  std::chrono::milliseconds settled{2000};
};

// Throws FileError if libhdf5 does not survive `path` (a crash, a signal, the time limits, memory,
// or the child's failure to start). An HDF5 error is not a failure here: the reader meets it
// again and reports it with its precise message. Thread-safe (one probe at a time).
void probe_hdf5_file(const std::filesystem::path& path);

// A file this process has just written in full (Hdf5File::create's on closing, write_image's):
// not probed while it stays as written (same inode, size and modification time; the rename of an
// atomic write keeps them). Its external links lead to files this process wrote or probed, as
// the writers build a file from one they read. A change in place by another process within the
// timestamp granularity would go unseen: damaged files, not racing writers, are what this guards
// against.
void note_hdf5_file_written(const std::filesystem::path& path);

// The limits for the following probes (the fuzz targets set a wall limit below libFuzzer's).
void set_hdf5_probe_limits(const Hdf5ProbeLimits& limits);
// Forgets which files passed (a fuzz target rewrites one file in place for each input).
void forget_probed_hdf5_files();

}  // namespace trapdem

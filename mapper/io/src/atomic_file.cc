// Crash-safe file replacement: temp file in the same directory, fsync, rename, fsync the
// directory. rename(2) within one file system is atomic, so readers (and a restarted process)
// see either the old file or the new one. Durability::kAtomic leaves out the two fsyncs.

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::mapper::io {
namespace {

[[noreturn]] void fail_errno(const std::filesystem::path& path, const char* what) {
  throw std::runtime_error(path.string() + ": " + what + ": " + std::strerror(errno));
}

/// Closes a file descriptor on scope exit.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void write_file_atomic_chunks(const std::filesystem::path& path,
                              const std::function<void(const ChunkSink&)>& produce,
                              Durability durability) {
  const bool sync = durability == Durability::kSynced;
  static std::atomic<unsigned long> counter{0};
  const std::filesystem::path dir =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);  // a missing folder is made, not an error
  if (ec) throw std::runtime_error(dir.string() + ": cannot create directory: " + ec.message());
  const std::filesystem::path temp =
      dir / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
             std::to_string(counter.fetch_add(1)));
  {
    Fd file{::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644)};
    if (file.fd < 0) fail_errno(temp, "cannot create");
    const ChunkSink emit = [&](std::string_view piece) {
      const char* data = piece.data();
      std::size_t left = piece.size();
      while (left > 0) {
        const ssize_t n = ::write(file.fd, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail_errno(temp, "cannot write");
        data += n;
        left -= static_cast<std::size_t>(n);
      }
    };
    try {
      produce(emit);
    } catch (...) {
      // A failed write or a failing producer leaves no temp file behind, and `path` untouched.
      const int saved = errno;
      ::unlink(temp.c_str());
      errno = saved;
      throw;
    }
    // The data must be on disk before the name points at it, or a crash could leave a
    // renamed but empty file.
    if (sync && ::fsync(file.fd) != 0) {
      ::unlink(temp.c_str());
      fail_errno(temp, "cannot fsync");
    }
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    ::unlink(temp.c_str());
    errno = saved;
    fail_errno(path, "cannot rename temp file over");
  }
  if (!sync) return;
  // The rename itself lives in the directory: sync it so the new name survives a crash.
  Fd directory{::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (directory.fd < 0) fail_errno(dir, "cannot open directory");
  if (::fsync(directory.fd) != 0) fail_errno(dir, "cannot fsync directory");
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content,
                       Durability durability) {
  write_file_atomic_chunks(
      path, [&](const ChunkSink& emit) { emit(content); }, durability);
}

bool is_temp_file_name(const std::string& name) {
  // "." name ".tmp" sep digits sep digits, sep '-' (this file) or '.' (render/png_io.cc).
  if (name.size() < 9 || name[0] != '.') return false;
  std::size_t end = name.size();
  for (int field = 0; field < 2; ++field) {
    std::size_t start = end;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(name[start - 1]))) --start;
    if (start == end || start == 0 || (name[start - 1] != '-' && name[start - 1] != '.')) {
      return false;
    }
    end = start - 1;
  }
  return end > 5 && name.compare(end - 4, 4, ".tmp") == 0;
}

std::size_t remove_stale_temp_files(const std::filesystem::path& dir) {
  std::size_t removed = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (!is_temp_file_name(entry.path().filename().string())) continue;
    std::error_code file_ec;
    if (entry.is_regular_file(file_ec) && std::filesystem::remove(entry.path(), file_ec)) ++removed;
  }
  return removed;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw std::runtime_error(path.string() + ": read error");
  return buffer.str();
}

}  // namespace cogmap::mapper::io

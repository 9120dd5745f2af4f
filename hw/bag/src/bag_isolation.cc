// The child process that reads a bag, and the byte format it sends its result back in (native
// endianness: the same binary on both ends of the pipe).
#include "bag_isolation.h"

#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>
#include <stdexcept>
#include <type_traits>

#include "bag_file_probe.h"

// A sanitizer's runtime reserves terabytes of address space for its shadow memory, and maps
// more as the program runs: an address-space cap would make it fail, not the bag.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || defined(__SANITIZE_HWADDRESS__)
#define COGMAP_BAG_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer) || __has_feature(hwaddress_sanitizer)
#define COGMAP_BAG_SANITIZED 1
#endif
#endif
#ifndef COGMAP_BAG_SANITIZED
// This file built without one, but linked into a program that has one (a fuzz target).
extern "C" {
void __asan_init() __attribute__((weak));
void __tsan_init() __attribute__((weak));
void __msan_init() __attribute__((weak));
}
#endif

namespace cogmap::hw::bag {
namespace {

// Where the child is, in memory the parent can read after a crash.
struct Progress {
  char topic[256];
  std::uint64_t index;
  bool started;
};

class Out {
 public:
  template <typename T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void str(const std::string& s) {
    pod<std::uint64_t>(s.size());
    bytes_ += s;
  }
  void doubles(const std::vector<double>& v) {
    pod<std::uint64_t>(v.size());
    bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class In {
 public:
  explicit In(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  T pod() {
    T v;
    take(&v, sizeof v);
    return v;
  }
  std::string str() {
    std::string s(pod<std::uint64_t>(), '\0');
    take(s.data(), s.size());
    return s;
  }
  std::vector<double> doubles() {
    std::vector<double> v(pod<std::uint64_t>());
    take(v.data(), v.size() * sizeof(double));
    return v;
  }

 private:
  void take(void* dst, std::size_t n) {
    if (n > bytes_.size() - pos_) throw std::runtime_error("bag reader: short reply from child");
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy must not get
    std::memcpy(dst, bytes_.data() + pos_, n);
    pos_ += n;
  }
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

constexpr std::uint8_t kOk = 0, kError = 1;

// "topic T, message K: " while the child reads a message, else "".
std::string place(const Progress& p) {
  return p.started ? "topic " + std::string(p.topic) + ", message " + std::to_string(p.index) + ": "
                   : "";
}

bool sanitized() {
#ifdef COGMAP_BAG_SANITIZED
  return true;
#else
  return &__asan_init != nullptr || &__tsan_init != nullptr || &__msan_init != nullptr;
#endif
}

// The address space this process maps now (VmSize), 0 when /proc cannot say.
std::uint64_t mapped_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  if (!(statm >> pages)) return 0;
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

std::uint64_t add(std::uint64_t a, std::uint64_t b) {
  return a > std::numeric_limits<std::uint64_t>::max() - b
             ? std::numeric_limits<std::uint64_t>::max()
             : a + b;
}

std::string gib(std::uint64_t bytes) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f GiB", static_cast<double>(bytes) / (1u << 30));
  return s;
}

std::string bag_size(std::uint64_t bytes) {
  if (bytes < 1'000'000) return std::to_string(bytes) + " bytes";
  char s[32];
  std::snprintf(s, sizeof s, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return s;
}

std::string encode(const BagContents& c) {
  Out o;
  o.pod(kOk);
  const StreamRequest& r = c.choice.request;
  o.str(r.sonar_topic);
  o.pod(r.sonar);
  o.str(r.odometry_topic);
  o.pod(r.odometry);
  o.str(c.choice.sonar_type);
  o.str(c.choice.odom_type);
  o.pod<std::uint64_t>(c.streams.sonar.size());
  for (const SonarMessage& m : c.streams.sonar) {
    o.pod<std::uint64_t>(m.index);
    o.pod(m.stamp_s);
    o.doubles(m.x_m);
    o.doubles(m.y_m);
    o.doubles(m.ranges_m);
  }
  o.pod<std::uint64_t>(c.streams.poses.size());
  for (const PoseMessage& p : c.streams.poses) {
    o.pod<std::uint64_t>(p.index);
    o.pod(p.stamp_s);
    o.pod(p.x_m);
    o.pod(p.y_m);
    o.pod(p.yaw_rad);
  }
  o.pod<std::uint64_t>(c.streams.tf_messages);
  o.str(c.streams.tf_parent);
  o.str(c.streams.tf_child);
  return o.bytes();
}

BagContents decode(const std::string& bytes) {
  In in(bytes);
  if (in.pod<std::uint8_t>() == kError) throw std::runtime_error(in.str());
  BagContents c;
  StreamRequest& r = c.choice.request;
  r.sonar_topic = in.str();
  r.sonar = in.pod<SonarEncoding>();
  r.odometry_topic = in.str();
  r.odometry = in.pod<OdometryEncoding>();
  c.choice.sonar_type = in.str();
  c.choice.odom_type = in.str();
  c.streams.sonar.resize(in.pod<std::uint64_t>());
  for (SonarMessage& m : c.streams.sonar) {
    m.index = in.pod<std::uint64_t>();
    m.stamp_s = in.pod<double>();
    m.x_m = in.doubles();
    m.y_m = in.doubles();
    m.ranges_m = in.doubles();
  }
  c.streams.poses.resize(in.pod<std::uint64_t>());
  for (PoseMessage& p : c.streams.poses) {
    p.index = in.pod<std::uint64_t>();
    p.stamp_s = in.pod<double>();
    p.x_m = in.pod<double>();
    p.y_m = in.pod<double>();
    p.yaw_rad = in.pod<double>();
  }
  c.streams.tf_messages = in.pod<std::uint64_t>();
  c.streams.tf_parent = in.str();
  c.streams.tf_child = in.str();
  return c;
}

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent reports the short reply
    done += static_cast<std::size_t>(n);
  }
}

std::string error_reply(const std::string& message) {
  Out o;
  o.pod(kError);
  o.str(message);
  return o.bytes();
}

[[noreturn]] void child(int fd, Progress* progress, const std::string& path,
                        const BagImportOptions& options, std::size_t max_transducers) {
  // Before anything reads the bag or loads the ROS libraries.
  const std::uint64_t content = bag_content_bytes(path);
  const std::uint64_t limit = limit_address_space(reader_memory_budget(content));
  std::string reply;
  try {
    BagContents c;
    c.choice = choose_topics(list_topics(path), options);
    c.choice.request.max_transducers = max_transducers;
    c.streams =
        read_streams(path, c.choice.request, [progress](const std::string& t, std::size_t i) {
          std::strncpy(progress->topic, t.c_str(), sizeof progress->topic - 1);
          progress->index = i;
          progress->started = true;
        });
    progress->started = false;  // the messages are read
    reply = encode(c);
  } catch (const std::bad_alloc&) {
    // The reader lets it through (ros_bag_reader.cc) for this: unwound, the memory is free.
    reply = error_reply(out_of_memory_message(place(*progress), limit, content));
  } catch (const std::exception& e) {
    reply = error_reply(e.what());
  } catch (...) {
    reply = error_reply("the ROS bag library threw an unknown exception");
  }
  write_all(fd, reply);
  ::close(fd);
  ::_exit(0);  // no destructors or atexit handlers of the parent's objects in the child
}

}  // namespace

// The budget must stay out of reach of any intact bag. What grows with the bag while the child
// reads it: rosbag's index (~64 bytes a message), the streams read (a PointCloud of 16 points,
// ~280 bytes in the file, becomes two vectors of 16 doubles, ~350 bytes with its own), and the
// reply encoded from them, each up to 3 times that for a moment while a vector or string
// doubles. A message takes at least ~80 bytes of the bag (a record header of ~45 bytes, an
// index entry of 12, a header stamp), so at worst ~6 bytes of memory a byte of the bag.
// Measured (docs/reliability.md "Limits"): a 211 MB bag of 200 000 clouds of 16 points and
// 200 000 odometry messages peaked at 330 MB of address space (334 MB read from a 34 MB bz2
// copy), 1 000 000 empty clouds and 10 000 odometry messages (101 MB) at 264 MB: 1.5 and 2.5
// bytes a byte, the ROS libraries' ~20 MB included. What does not grow with the bag: rosbag's
// and the index check's chunk buffers (a chunk is at most 256 MiB unpacked, held packed and
// unpacked) and one message decoded whole (at most its chunk; roscpp_serialization's objects
// for it at most ~7 times that, for a cloud of empty channels): under 4 GiB. Hence 4 GiB plus
// 16 times the content; a damaged length the layout check misses that asks for more (2^31
// points of 12 bytes: 24 GiB) ends in std::bad_alloc at once instead of paging the machine.
std::uint64_t reader_memory_budget(std::uint64_t content_bytes) {
  constexpr std::uint64_t kFixed = std::uint64_t{4} << 30, kPerByte = 16;
  const std::uint64_t grows = content_bytes > std::numeric_limits<std::uint64_t>::max() / kPerByte
                                  ? std::numeric_limits<std::uint64_t>::max()
                                  : content_bytes * kPerByte;
  return add(kFixed, grows);
}

bool reader_memory_is_limited() { return !sanitized(); }

std::uint64_t limit_address_space(std::uint64_t budget) {
  if (sanitized()) return 0;
  const std::uint64_t mapped = mapped_bytes();
  if (mapped == 0) return 0;
  const std::uint64_t limit = add(mapped, budget);
  rlimit current{};
  if (::getrlimit(RLIMIT_AS, &current) != 0) return 0;
  if (current.rlim_cur != RLIM_INFINITY && current.rlim_cur <= limit) return current.rlim_cur;
  const rlimit capped{static_cast<rlim_t>(limit), current.rlim_max};
  if (::setrlimit(RLIMIT_AS, &capped) != 0) return 0;
  return limit;
}

std::string out_of_memory_message(const std::string& where, std::uint64_t limit,
                                  std::uint64_t content_bytes) {
  const std::string what = where.empty() ? "the bag" : "this message";
  if (limit == 0) {
    return where + "ran out of memory reading " + what +
           ": a length in the bag is damaged (or the bag is too large for this machine)";
  }
  return where + "ran out of memory reading " + what + " (the bag reader may map " + gib(limit) +
         " for this bag of " + bag_size(content_bytes) +
         ", more than an intact bag needs): a length in the bag is damaged";
}

BagContents read_bag_isolated(const std::string& path, const BagImportOptions& options,
                              std::size_t max_transducers) {
  void* shared =
      ::mmap(nullptr, sizeof(Progress), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (shared == MAP_FAILED) throw std::runtime_error("bag reader: mmap failed");
  auto* progress = new (shared) Progress{};
  struct Unmap {
    void* p;
    ~Unmap() { ::munmap(p, sizeof(Progress)); }
  } unmap{shared};
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("bag reader: pipe failed");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error("bag reader: fork failed");
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], progress, path, options, max_transducers);
  }
  ::close(fds[1]);
  std::string reply;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    reply.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    throw std::runtime_error(place(*progress) + "the ROS bag library crashed (signal " +
                             std::to_string(sig) + ", " + ::strsignal(sig) +
                             ") reading this message: the bag is corrupt");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || reply.empty()) {
    throw std::runtime_error("the bag reader process failed (exit status " +
                             std::to_string(WEXITSTATUS(status)) + ")");
  }
  return decode(reply);
}

}  // namespace cogmap::hw::bag

#include "generators/checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_set>

#include "generators/row_runner.hpp"
#include "lookup/detail/sha256.hpp"
#include "tablewrite/temp_file.hpp"

namespace brdftab::gen {

static_assert(std::endian::native == std::endian::little, "the checkpoint layout is little-endian");

namespace {

using lookup::detail::Sha256;

constexpr const char* kMagic = "brdftab-checkpoint 1";

std::string header_text(const std::string& key, const std::string& file) {
  const std::string lines = std::string(kMagic) + "\ncontent_key " + key + "\nfile " + file + "\n";
  const auto d = Sha256::of(reinterpret_cast<const unsigned char*>(lines.data()), lines.size());
  return lines + "digest " + Sha256::hex(d) + "\n";
}

template <class T>
void put(std::string& b, T v) {
  b.append(reinterpret_cast<const char*>(&v), sizeof v);
}
void put_text(std::string& b, const std::string& s) {
  put<std::uint16_t>(b, static_cast<std::uint16_t>(s.size()));
  b += s;
}

// Reads from a record body; ok turns false on running past its end.
struct Reader {
  const char* p;
  const char* end;
  bool ok = true;
  template <class T>
  T get() {
    T v{};
    if (end - p < static_cast<std::ptrdiff_t>(sizeof v)) return ok = false, v;
    std::memcpy(&v, p, sizeof v);
    p += sizeof v;
    return v;
  }
  std::string text(std::size_t n) {
    if (static_cast<std::size_t>(end - p) < n) return ok = false, std::string();
    std::string s(p, n);
    p += n;
    return s;
  }
};

void write_all(int fd, const std::string& b, const std::filesystem::path& path) {
  std::size_t done = 0;
  while (done < b.size()) {
    const ssize_t w = ::write(fd, b.data() + done, b.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) throw std::runtime_error("checkpoint '" + path.string() + "': write failed: " + std::strerror(errno));
    done += static_cast<std::size_t>(w);
  }
}

}  // namespace

std::filesystem::path Checkpoint::path_for(const std::filesystem::path& table_file) {
  return table_file.string() + ".checkpoint";
}

std::string Checkpoint::request_key(const RowJobs& jobs, std::size_t i) {
  Sha256 h;
  const auto text = [&h](const std::string& s) {
    const std::uint64_t n = s.size();
    h.update(&n, sizeof n);
    h.update(s.data(), s.size());
  };
  text(jobs.dataset);
  text(jobs.stage);
  const std::uint64_t index = i;
  h.update(&index, sizeof index);
  const auto outer = jobs.outer_of(i), last = jobs.last_of(i);
  const std::uint64_t no = outer.size(), nl = last.size();
  h.update(&no, sizeof no);
  h.update(outer.data(), outer.size() * sizeof(double));
  h.update(&nl, sizeof nl);
  h.update(last.data(), last.size() * sizeof(double));
  const auto d = h.finish();
  return std::string(reinterpret_cast<const char*>(d.data()), 16);
}

Checkpoint::Checkpoint(const std::filesystem::path& table_file, const std::string& content_key, std::ostream& log,
                       bool discard_foreign)
    : path_(path_for(table_file)), key_(content_key), file_name_(table_file.filename().string()) {
  load(log, discard_foreign);
}

void Checkpoint::load(std::ostream& log, bool discard_foreign) {
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) {
    create_fresh();
    return;
  }
  std::string data;
  {
    std::ifstream in(path_, std::ios::binary);
    data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) throw std::runtime_error("checkpoint '" + path_.string() + "': cannot read it");
  }
  const auto discard = [&](const std::string& why) {
    log << "checkpoint " << path_.string() << " is damaged (" << why << "): discarded, starting afresh\n";
    rows_.clear();
    create_fresh();
  };
  // Header: four lines, the digest over the first three.
  std::size_t pos = 0;
  std::vector<std::string> lines;
  for (int k = 0; k < 4; ++k) {
    const std::size_t nl = data.find('\n', pos);
    if (nl == std::string::npos || nl - pos > 4096) return discard("no complete header");
    lines.push_back(data.substr(pos, nl - pos));
    pos = nl + 1;
  }
  const std::string stored_key = lines[1].rfind("content_key ", 0) == 0 ? lines[1].substr(12) : "";
  const std::string stored_file = lines[2].rfind("file ", 0) == 0 ? lines[2].substr(5) : "";
  if (lines[0] != kMagic || data.compare(0, pos, header_text(stored_key, stored_file)) != 0)
    return discard("header or its digest does not match");
  if (stored_key != key_ || stored_file != file_name_) {
    const std::string what = "checkpoint " + path_.string() + " belongs to " + stored_file + " with content key " +
                             stored_key.substr(0, 12) + "..., not to this run's " + file_name_ + " with content key " +
                             key_.substr(0, 12) + "... (another manifest entry, scene or brdftab version)";
    if (!discard_foreign)
      throw CheckpointRefused(what + "; refused: remove it, or pass --discard-checkpoint to start afresh");
    log << what << ": discarded (--discard-checkpoint)\n";
    create_fresh();
    return;
  }
  // Records.
  std::unordered_set<std::string> seen;
  while (pos < data.size()) {
    std::uint32_t len = 0;
    if (data.size() - pos < 4 + 32) break;  // unfinished record
    std::memcpy(&len, data.data() + pos, 4);
    if (data.size() - pos - 4 < static_cast<std::size_t>(len) + 32) break;  // unfinished record
    const char* body = data.data() + pos + 4;
    const auto d = Sha256::of(reinterpret_cast<const unsigned char*>(body), len);
    if (std::memcmp(d.data(), body + len, 32) != 0)
      return discard("the record at byte " + std::to_string(pos) + " fails its SHA-256 digest");
    Reader r{body, body + len};
    const std::string dataset = r.text(r.get<std::uint16_t>());
    const std::string stage = r.text(r.get<std::uint16_t>());
    r.get<std::uint64_t>();
    const std::string key = r.text(16);
    const std::uint32_t n = r.get<std::uint32_t>();
    if (!r.ok || static_cast<std::size_t>(r.end - r.p) != std::size_t(n) * sizeof(double))
      return discard("the record at byte " + std::to_string(pos) + " has a wrong layout");
    if (!seen.insert(key).second) return discard("a row is recorded twice (record at byte " + std::to_string(pos) + ")");
    std::vector<double> v(n);
    std::memcpy(v.data(), r.p, std::size_t(n) * sizeof(double));
    rows_.emplace(key, std::move(v));
    pos += 4 + len + 32;
  }
  loaded_ = rows_.size();
  if (pos < data.size()) {
    log << "checkpoint " << path_.string() << ": dropped an unfinished record at its end (" << data.size() - pos
        << " bytes, a write cut short)\n";
    if (::truncate(path_.c_str(), static_cast<off_t>(pos)) != 0)
      throw std::runtime_error("checkpoint '" + path_.string() + "': cannot truncate it: " + std::strerror(errno));
  }
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error("checkpoint '" + path_.string() + "': cannot open it: " + std::strerror(errno));
  log << "checkpoint " << path_.string() << ": resuming with " << loaded_ << " finished rows\n";
}

void Checkpoint::create_fresh() {
  if (fd_ >= 0) ::close(fd_), fd_ = -1;
  std::error_code ec;
  std::filesystem::create_directories(path_.parent_path().empty() ? "." : path_.parent_path(), ec);
  tablewrite::TempFile temp(path_);
  {
    std::ofstream out(temp.path(), std::ios::binary | std::ios::trunc);
    out << header_text(key_, file_name_);
    out.flush();
    if (!out) throw std::runtime_error("checkpoint '" + path_.string() + "': cannot write it");
  }
  temp.commit();
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error("checkpoint '" + path_.string() + "': cannot open it: " + std::strerror(errno));
  loaded_ = 0;
}

Checkpoint::~Checkpoint() {
  if (fd_ >= 0) {
    ::fdatasync(fd_);
    ::close(fd_);
  }
}

const std::vector<double>* Checkpoint::find(const RowJobs& jobs, std::size_t i) const {
  if (rows_.empty()) return nullptr;
  const auto it = rows_.find(request_key(jobs, i));
  return it == rows_.end() ? nullptr : &it->second;
}

void Checkpoint::append(const RowJobs& jobs, std::size_t i, std::span<const double> values) {
  std::string body;
  put_text(body, jobs.dataset);
  put_text(body, jobs.stage);
  put<std::uint64_t>(body, i);
  body += request_key(jobs, i);
  put<std::uint32_t>(body, static_cast<std::uint32_t>(values.size()));
  body.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  std::string rec;
  put<std::uint32_t>(rec, static_cast<std::uint32_t>(body.size()));
  rec += body;
  const auto d = Sha256::of(reinterpret_cast<const unsigned char*>(body.data()), body.size());
  rec.append(reinterpret_cast<const char*>(d.data()), d.size());
  std::lock_guard lock(mutex_);
  if (fd_ < 0) return;
  write_all(fd_, rec, path_);
  if (std::chrono::steady_clock::now() - last_sync_ > sync_interval) {
    ::fdatasync(fd_);
    last_sync_ = std::chrono::steady_clock::now();
  }
}

void Checkpoint::sync() {
  std::lock_guard lock(mutex_);
  if (fd_ >= 0) ::fdatasync(fd_);
  last_sync_ = std::chrono::steady_clock::now();
}

void Checkpoint::remove() {
  std::lock_guard lock(mutex_);
  if (fd_ >= 0) ::close(fd_), fd_ = -1;
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

}  // namespace brdftab::gen

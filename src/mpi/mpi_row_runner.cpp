#include "src/mpi/mpi_row_runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <deque>
#include <iostream>
#include <mutex>
#include <optional>
#include <thread>

namespace brdftab::mpi {

namespace {

enum Tag : int { kRequest = 101, kGrant = 102, kResult = 103, kFail = 104, kEnd = 105 };

// What each compute thread is working on, readable from a signal handler: a fixed table of
// text slots (written before a row starts, cleared after).
constexpr int kSlots = 64;
std::array<std::array<char, 320>, kSlots> g_current{};
int g_rank = 0;
std::int64_t g_stage = 0;  // stages run by this process, over all runners

extern "C" void on_death(int sig) {
  char head[96];
  const int n = std::snprintf(head, sizeof head, "brdftab generate: rank %d ended by signal %d", g_rank, sig);
  [[maybe_unused]] ssize_t w = ::write(STDERR_FILENO, head, static_cast<std::size_t>(n));
  bool any = false;
  for (auto& slot : g_current)
    if (slot[0]) {
      w = ::write(STDERR_FILENO, any ? "; " : " while computing ", any ? 2 : 17);
      w = ::write(STDERR_FILENO, slot.data(), ::strnlen(slot.data(), slot.size()));
      any = true;
    }
  w = ::write(STDERR_FILENO, "\n", 1);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// A pool of compute threads fed with row indices; finished indices (and a failure) are
// handed back to the thread that owns the pool.
class Pool {
 public:
  Pool(int threads, const gen::RowJobs& jobs, const gen::RowFunction& row, std::span<double> out) {
    for (int t = 0; t < threads; ++t)
      threads_.emplace_back([this, t, &jobs, &row, out] { loop(t, jobs, row, out); });
  }
  ~Pool() {
    {
      std::lock_guard lock(m_);
      closing_ = true;
      queue_.clear();
    }
    work_cv_.notify_all();
    for (auto& t : threads_) t.join();
  }
  void add(const std::vector<std::size_t>& rows) {
    {
      std::lock_guard lock(m_);
      queue_.insert(queue_.end(), rows.begin(), rows.end());
    }
    work_cv_.notify_all();
  }
  // Takes up to n queued rows (to deal them elsewhere).
  std::vector<std::size_t> take(std::size_t n) {
    std::lock_guard lock(m_);
    n = std::min(n, queue_.size());
    std::vector<std::size_t> r(queue_.end() - static_cast<std::ptrdiff_t>(n), queue_.end());
    queue_.erase(queue_.end() - static_cast<std::ptrdiff_t>(n), queue_.end());
    return r;
  }
  std::size_t queued() {
    std::lock_guard lock(m_);
    return queue_.size();
  }
  std::size_t load() {  // queued + running
    std::lock_guard lock(m_);
    return queue_.size() + busy_;
  }
  // Waits up to `timeout` for a finished row; returns those finished so far.
  std::vector<std::size_t> finished(std::chrono::microseconds timeout) {
    std::unique_lock lock(m_);
    if (done_.empty() && !failure_) done_cv_.wait_for(lock, timeout);
    std::vector<std::size_t> d;
    d.swap(done_);
    return d;
  }
  std::optional<std::pair<std::size_t, std::string>> failure() {
    std::lock_guard lock(m_);
    return failure_;
  }

 private:
  void loop(int t, const gen::RowJobs& jobs, const gen::RowFunction& row, std::span<double> out) {
    auto& slot = g_current[static_cast<std::size_t>(t % kSlots)];
    for (;;) {
      std::size_t i;
      {
        std::unique_lock lock(m_);
        work_cv_.wait(lock, [&] { return closing_ || !queue_.empty(); });
        if (queue_.empty()) return;
        i = queue_.front();
        queue_.pop_front();
        ++busy_;
      }
      const std::string label = gen::row_label(jobs, i);
      std::snprintf(slot.data(), slot.size(), "%s", label.c_str());
      std::optional<std::string> error;
      try {
        gen::run_row(jobs, i, row, out);
      } catch (const std::exception& e) {
        error = e.what();
      } catch (...) {
        error = "unknown exception";
      }
      slot[0] = 0;
      {
        std::lock_guard lock(m_);
        --busy_;
        if (error) {
          if (!failure_) failure_.emplace(i, *error);
        } else {
          done_.push_back(i);
        }
      }
      done_cv_.notify_all();
    }
  }
  std::mutex m_;
  std::condition_variable work_cv_, done_cv_;
  std::deque<std::size_t> queue_;
  std::vector<std::size_t> done_;
  std::size_t busy_ = 0;
  bool closing_ = false;
  std::optional<std::pair<std::size_t, std::string>> failure_;
  std::vector<std::thread> threads_;
};

struct Header {
  std::int64_t stage, index;
};

// Polls for a message of any tag from `source`; true with its status if there is one.
bool probe(MPI_Comm comm, int source, MPI_Status& st) {
  int flag = 0;
  MPI_Iprobe(source, MPI_ANY_TAG, comm, &flag, &st);
  return flag != 0;
}

std::vector<char> receive(MPI_Comm comm, const MPI_Status& st) {
  int bytes = 0;
  MPI_Get_count(&st, MPI_BYTE, &bytes);
  std::vector<char> buf(static_cast<std::size_t>(bytes));
  MPI_Recv(buf.data(), bytes, MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG, comm, MPI_STATUS_IGNORE);
  return buf;
}

void broadcast(MPI_Comm comm, std::span<double> out) {
  constexpr std::size_t kChunk = std::size_t(1) << 26;
  for (std::size_t k = 0; k < out.size(); k += kChunk)
    MPI_Bcast(out.data() + k, static_cast<int>(std::min(kChunk, out.size() - k)), MPI_DOUBLE, 0, comm);
}

// A row's outer coordinates, bit for bit (rows of two tables with the same key share the
// exact values a family caches in the process that computed them).
std::string coordinates_key(const gen::RowJobs& jobs, std::size_t i) {
  const std::span<const double> x = jobs.outer_of(i);
  return std::string(reinterpret_cast<const char*>(x.data()), x.size_bytes());
}

}  // namespace

void install_death_messages(int rank) {
  g_rank = rank;
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTERM}) std::signal(sig, on_death);
}

MpiRowRunner::MpiRowRunner(MPI_Comm comm, gen::Checkpoint* checkpoint, int threads)
    : comm_(comm), threads_(std::max(1, threads)), checkpoint_(checkpoint) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

void MpiRowRunner::run(const gen::RowJobs& jobs, const gen::RowFunction& row, std::span<double> out,
                       const gen::GenerateContext& ctx) {
  stage_ = ++g_stage;  // the same sequence on every rank (they run the same stages)
  if (rank_ == 0)
    deal(jobs, row, out, ctx);
  else
    work(jobs, row, out);
  broadcast(comm_, out);
}

void MpiRowRunner::fail(int rank, const gen::RowJobs& jobs, std::size_t index, const std::string& what) {
  std::cerr << "brdftab generate: rank " << rank << " failed on " << gen::row_label(jobs, index) << ": " << what;
  if (checkpoint_) {
    checkpoint_->sync();
    std::cerr << "; no table file written, the checkpoint " << checkpoint_->path().string() << " keeps the finished rows";
  }
  std::cerr << std::endl;
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}

void MpiRowRunner::deal(const gen::RowJobs& jobs, const gen::RowFunction& row, std::span<double> out,
                        const gen::GenerateContext& ctx) {
  const std::vector<std::size_t> todo = gen::rows_to_compute(jobs, checkpoint_, out);
  rows_resumed += jobs.count - todo.size();
  rows_computed += todo.size();
  std::size_t received = 0;
  const std::string stage_text = jobs.dataset + ": " + jobs.stage;
  // Affinity: rows whose coordinates rank r computed in an earlier stage wait in claimed[r];
  // the others (and rank 0's) go to rank 0's pool.
  std::vector<int> before(jobs.count, -1), computed_by(jobs.count, -1);
  std::vector<std::deque<std::size_t>> claimed(static_cast<std::size_t>(size_));
  std::vector<std::size_t> unclaimed;
  for (std::size_t i : todo) {
    if (auto it = owner_.find(coordinates_key(jobs, i)); it != owner_.end()) before[i] = it->second;
    if (before[i] > 0)
      claimed[static_cast<std::size_t>(before[i])].push_back(i);
    else
      unclaimed.push_back(i);
  }
  const auto record = [&](std::size_t i, int rank) {
    if (checkpoint_)
      checkpoint_->append(jobs, i, std::span<const double>(out.data() + jobs.offset[i], jobs.offset[i + 1] - jobs.offset[i]));
    computed_by[i] = rank;
    ++received;
  };
  // Up to n rows from the back of the longest claimed queue other than `except`'s, of a rank
  // not served for `patience`.
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const auto patience = std::chrono::duration<double>(std::clamp(row_seconds_, 0.1, 10.0));
  // A rank's claimed rows wait for its first request of the stage (a rank late from the last
  // stage's broadcast is not slow), then for `patience` after each grant.
  std::vector<std::optional<Clock::time_point>> served(static_cast<std::size_t>(size_));
  const auto steal = [&](int except, std::size_t n) {
    std::deque<std::size_t>* from = nullptr;
    const Clock::time_point now = Clock::now();
    for (int r = 1; r < size_; ++r)
      if (r != except && !claimed[static_cast<std::size_t>(r)].empty() &&
          served[static_cast<std::size_t>(r)] && now - *served[static_cast<std::size_t>(r)] > patience &&
          (!from || claimed[static_cast<std::size_t>(r)].size() > from->size()))
        from = &claimed[static_cast<std::size_t>(r)];
    std::vector<std::size_t> rows;
    while (from && !from->empty() && rows.size() < n) rows.push_back(from->back()), from->pop_back();
    return rows;
  };
  const auto any_claimed = [&] {
    return std::any_of(claimed.begin(), claimed.end(), [](const auto& q) { return !q.empty(); });
  };
  struct Request {
    int rank;
    std::size_t want;
  };
  std::vector<Request> deferred;  // requests answered once claimed rows may be stolen
  std::vector<std::optional<Clock::time_point>> first_served(static_cast<std::size_t>(size_));
  std::vector<std::size_t> returned(static_cast<std::size_t>(size_));  // rows each rank returned this stage
  const auto grant = [&](int rank, const std::vector<std::size_t>& rows) {
    served[static_cast<std::size_t>(rank)] = Clock::now();
    if (!first_served[static_cast<std::size_t>(rank)]) first_served[static_cast<std::size_t>(rank)] = served[static_cast<std::size_t>(rank)];
    rows_dealt += rows.size();
    std::vector<std::int64_t> msg{stage_};
    msg.insert(msg.end(), rows.begin(), rows.end());
    MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_INT64_T, rank, kGrant, comm_);
  };
  {
    Pool pool(threads_, jobs, row, out);
    // Rank 0's threads take rows from the front, the other ranks are dealt from the back.
    pool.add(unclaimed);
    auto idle = std::chrono::microseconds(100);
    auto last_report = std::chrono::steady_clock::now();
    while (received < todo.size()) {
      bool active = false;
      for (std::size_t i : pool.finished(idle)) record(i, 0), active = true;
      if (auto f = pool.failure()) fail(0, jobs, f->first, f->second);
      // Rank 0 idle with nothing unclaimed: it takes a row claimed by another rank.
      if (pool.queued() == 0 && pool.load() < static_cast<std::size_t>(threads_)) {
        const std::vector<std::size_t> rows = steal(0, 1);
        if (!rows.empty()) pool.add(rows), active = true;
      }
      MPI_Status st;
      while (probe(comm_, MPI_ANY_SOURCE, st)) {
        active = true;
        ++messages;
        const std::vector<char> buf = receive(comm_, st);
        Header h{};
        std::memcpy(&h, buf.data(), std::min(buf.size(), sizeof h));
        // A request a rank sent just before the end of an earlier stage: its answer is END.
        if (st.MPI_TAG == kRequest && buf.size() >= sizeof h && h.stage < stage_) continue;
        if (buf.size() < sizeof h || h.stage != stage_) {
          std::cerr << "brdftab generate: rank " << st.MPI_SOURCE << " sent a message of another stage (" << h.stage
                    << ", expected " << stage_ << ")" << std::endl;
          MPI_Abort(MPI_COMM_WORLD, 1);
        }
        if (st.MPI_TAG == kRequest) {
          // Guided dealing: blocks shrink as the stage empties (row costs vary 1000x).
          // Its claimed rows first, as many as it has returned in 50 ms so far this stage (cached
          // rows are cheap: a message per row would leave the rank waiting; costly ones go a
          // few at a time, so they stay free to be stolen), then unclaimed rows, then rows
          // claimed by the busiest rank.
          const std::size_t want = static_cast<std::size_t>(std::max<std::int64_t>(1, h.index));
          const auto src = static_cast<std::size_t>(st.MPI_SOURCE);
          std::deque<std::size_t>& own = claimed[src];
          std::vector<std::size_t> rows;
          std::size_t own_block = want;
          if (served[src] && returned[src] > 0) {
            const double seconds = std::max(1e-6, std::chrono::duration<double>(Clock::now() - *first_served[src]).count());
            const double rows_in_50ms = std::min(0.05 * static_cast<double>(returned[src]) / seconds, static_cast<double>(own.size()));
            own_block = std::max(want, static_cast<std::size_t>(rows_in_50ms));
          }
          while (!own.empty() && rows.size() < own_block) rows.push_back(own.front()), own.pop_front();
          if (rows.empty()) {
            const std::size_t share = std::max<std::size_t>(1, pool.queued() / (2 * static_cast<std::size_t>(size_)));
            rows = pool.take(std::min(want, share));
          }
          if (rows.empty()) rows = steal(st.MPI_SOURCE, want);
          // Nothing to give yet, but claimed rows that may come free: an empty grant would end
          // the rank's stage, so it hears back (one row, stolen once patience runs out) later.
          if (rows.empty() && any_claimed())
            deferred.push_back({st.MPI_SOURCE, want});
          else
            grant(st.MPI_SOURCE, rows);
        } else if (st.MPI_TAG == kResult) {
          const std::size_t i = static_cast<std::size_t>(h.index);
          const std::size_t n = (buf.size() - sizeof h) / sizeof(double);
          if (i >= jobs.count || n != jobs.offset[i + 1] - jobs.offset[i]) {
            std::cerr << "brdftab generate: rank " << st.MPI_SOURCE << " sent a malformed row result" << std::endl;
            MPI_Abort(MPI_COMM_WORLD, 1);
          }
          std::memcpy(out.data() + jobs.offset[i], buf.data() + sizeof h, n * sizeof(double));
          record(i, st.MPI_SOURCE);
          ++returned[static_cast<std::size_t>(st.MPI_SOURCE)];
        } else if (st.MPI_TAG == kFail) {
          fail(st.MPI_SOURCE, jobs, static_cast<std::size_t>(h.index), std::string(buf.begin() + sizeof h, buf.end()));
        }
      }
      for (std::size_t k = 0; k < deferred.size();) {
        std::vector<std::size_t> rows = steal(deferred[k].rank, deferred[k].want);
        if (rows.empty() && any_claimed()) {
          ++k;
          continue;
        }
        grant(deferred[k].rank, rows);  // rows stolen, or none left to claim: the rank's stage ends
        deferred.erase(deferred.begin() + static_cast<std::ptrdiff_t>(k));
        active = true;
      }
      idle = active ? std::chrono::microseconds(100) : std::min(idle * 2, std::chrono::microseconds(2000));
      if (std::chrono::steady_clock::now() - last_report > std::chrono::milliseconds(200)) {
        ctx.report(stage_text, todo.empty() ? 1.0 : static_cast<double>(received) / static_cast<double>(todo.size()));
        last_report = std::chrono::steady_clock::now();
      }
    }
  }
  if (checkpoint_) checkpoint_->sync();
  if (!todo.empty()) {
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    row_seconds_ = std::max(row_seconds_, seconds * size_ * threads_ / static_cast<double>(todo.size()));
  }
  for (std::size_t i : todo) {
    rows_shared += before[i] >= 0;
    rows_affine += before[i] >= 0 && before[i] == computed_by[i];
    owner_[coordinates_key(jobs, i)] = computed_by[i];
  }
  for (int r = 1; r < size_; ++r) MPI_Send(&stage_, 1, MPI_INT64_T, r, kEnd, comm_);
  ctx.report(stage_text, 1.0);
}

void MpiRowRunner::work(const gen::RowJobs& jobs, const gen::RowFunction& row, std::span<double> out) {
  Pool pool(threads_, jobs, row, out);
  bool asked = false, dealt_out = false;
  auto idle = std::chrono::microseconds(100);
  for (;;) {
    bool active = false;
    for (std::size_t i : pool.finished(idle)) {
      active = true;
      const std::size_t n = jobs.offset[i + 1] - jobs.offset[i];
      std::vector<char> msg(sizeof(Header) + n * sizeof(double));
      const Header h{stage_, static_cast<std::int64_t>(i)};
      std::memcpy(msg.data(), &h, sizeof h);
      std::memcpy(msg.data() + sizeof h, out.data() + jobs.offset[i], n * sizeof(double));
      MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_BYTE, 0, kResult, comm_);
    }
    if (auto f = pool.failure()) {
      std::vector<char> msg(sizeof(Header) + f->second.size());
      const Header h{stage_, static_cast<std::int64_t>(f->first)};
      std::memcpy(msg.data(), &h, sizeof h);
      std::memcpy(msg.data() + sizeof h, f->second.data(), f->second.size());
      MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_BYTE, 0, kFail, comm_);
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // rank 0 ends the job
    }
    // Keep every thread busy and one row in reserve.
    const std::size_t load = pool.load();
    if (!asked && !dealt_out && load < static_cast<std::size_t>(threads_)) {
      const Header h{stage_, static_cast<std::int64_t>(threads_ + 1 - load)};
      MPI_Send(&h, sizeof h, MPI_BYTE, 0, kRequest, comm_);
      asked = true;
    }
    MPI_Status st;
    bool ended = false;
    while (probe(comm_, 0, st)) {
      active = true;
      if (st.MPI_TAG == kGrant) {
        int n = 0;
        MPI_Get_count(&st, MPI_INT64_T, &n);
        std::vector<std::int64_t> msg(static_cast<std::size_t>(n));
        MPI_Recv(msg.data(), n, MPI_INT64_T, 0, kGrant, comm_, MPI_STATUS_IGNORE);
        asked = false;
        if (msg.size() <= 1) dealt_out = true;
        pool.add(std::vector<std::size_t>(msg.begin() + 1, msg.end()));
      } else if (st.MPI_TAG == kEnd) {
        std::int64_t s = 0;
        MPI_Recv(&s, 1, MPI_INT64_T, 0, kEnd, comm_, MPI_STATUS_IGNORE);
        ended = true;
        break;
      } else {
        std::cerr << "brdftab generate: rank " << rank_ << ": unexpected message tag " << st.MPI_TAG << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    }
    if (ended) break;
    idle = active ? std::chrono::microseconds(100) : std::min(idle * 2, std::chrono::microseconds(2000));
  }
}

}  // namespace brdftab::mpi
